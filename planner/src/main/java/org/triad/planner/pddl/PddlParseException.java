package org.triad.planner.pddl;

/** Bad PDDL input: carries the source position so callers can print {@code source:line:col: message}. */
public class PddlParseException extends RuntimeException {
    private static final long serialVersionUID = 1L;
    private final String source;
    private final int line;
    private final int column;
    private final String detail;

    public PddlParseException(String source, int line, int column, String detail) {
        super((source == null ? "" : source + ":") + line + ":" + column + ": " + detail);
        this.source = source;
        this.line = line;
        this.column = column;
        this.detail = detail;
    }

    public String source() { return source; }
    public int line() { return line; }
    public int column() { return column; }
    /** The message without the location prefix. */
    public String detail() { return detail; }
}
