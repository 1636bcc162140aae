package org.triad.planner.pddl;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import java.util.Locale;

/** A parsed s-expression node with its source position: a symbol or a list. */
final class SExpr {
    /**
     * Deepest nesting accepted. Real domains nest a dozen levels (the IPC corpus at most 9); the limit keeps the recursive
     * passes over formulas (parsing, normalisation, printing) far from the thread's stack size
     * whatever the input, and turns absurd input into a located error instead of a StackOverflowError.
     */
    static final int MAX_DEPTH = 256;

    final String symbol; // null for a list
    final List<SExpr> items;
    final int line;
    final int column;

    private SExpr(String symbol, List<SExpr> items, int line, int column) {
        this.symbol = symbol;
        this.items = items;
        this.line = line;
        this.column = column;
    }

    boolean isList() { return symbol == null; }

    boolean isSymbol(String s) { return symbol != null && symbol.equals(s); }

    /** The head symbol of a list, or null. */
    String head() {
        return isList() && !items.isEmpty() && !items.get(0).isList() ? items.get(0).symbol : null;
    }

    @Override
    public String toString() {
        if (!isList()) return symbol;
        StringBuilder sb = new StringBuilder("(");
        for (int i = 0; i < items.size(); i++) {
            if (i > 0) sb.append(' ');
            sb.append(items.get(i));
        }
        return sb.append(')').toString();
    }

    /**
     * Reads exactly one top-level expression, in one pass without recursion. Lexical rules as in
     * PDDL: names are case-insensitive (lower-cased here); a name ends at white space, a
     * parenthesis, a comment ({@code ;} to the end of the line) or a {@code ?} that starts a
     * variable, so {@code (aircraft?a)} is {@code (aircraft ?a)}.
     */
    static SExpr read(String text, String source) {
        Reader r = new Reader(text, source);
        r.skipBlank();
        if (r.pos >= text.length()) throw r.error("empty input: expected '(define ...)'");
        SExpr e = r.expr();
        r.skipBlank();
        if (r.pos < text.length()) throw r.error("unexpected text after the closing ')' of the definition");
        return e;
    }

    private static final class Reader {
        final String text;
        final String source;
        int pos;
        int line = 1;
        int col = 1;

        Reader(String text, String source) {
            this.text = text;
            this.source = source;
        }

        PddlParseException error(String msg) {
            return new PddlParseException(source, line, col, msg);
        }

        void advance() {
            if (text.charAt(pos) == '\n') {
                line++;
                col = 1;
            } else {
                col++;
            }
            pos++;
        }

        void skipBlank() {
            while (pos < text.length()) {
                char c = text.charAt(pos);
                if (c == ';') {
                    while (pos < text.length() && text.charAt(pos) != '\n') advance();
                } else if (Character.isWhitespace(c)) {
                    advance();
                } else {
                    return;
                }
            }
        }

        /** An open list being read: its items so far and where it started. */
        private record Open(List<SExpr> items, int line, int column) { }

        SExpr expr() {
            if (text.charAt(pos) == ')') throw error("unexpected ')'");
            if (text.charAt(pos) != '(') return symbol();
            Deque<Open> open = new ArrayDeque<>();
            while (true) {
                skipBlank();
                if (pos >= text.length()) {
                    Open o = open.peek();
                    throw new PddlParseException(source, o.line, o.column, "unbalanced '(': missing ')' before end of input");
                }
                char c = text.charAt(pos);
                if (c == '(') {
                    if (open.size() >= MAX_DEPTH) {
                        throw error("expressions nested deeper than " + MAX_DEPTH + " levels");
                    }
                    open.push(new Open(new ArrayList<>(), line, col));
                    advance();
                } else if (c == ')') {
                    advance();
                    Open o = open.pop();
                    SExpr done = new SExpr(null, o.items, o.line, o.column);
                    if (open.isEmpty()) return done;
                    open.peek().items.add(done);
                } else {
                    open.peek().items.add(symbol());
                }
            }
        }

        private SExpr symbol() {
            int l = line, co = col;
            int start = pos;
            while (pos < text.length()) {
                char d = text.charAt(pos);
                if (Character.isWhitespace(d) || d == '(' || d == ')' || d == ';' || (d == '?' && pos > start)) break;
                advance();
            }
            return new SExpr(text.substring(start, pos).toLowerCase(Locale.ROOT), null, l, co);
        }
    }
}
