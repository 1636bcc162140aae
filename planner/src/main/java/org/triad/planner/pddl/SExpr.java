package org.triad.planner.pddl;

import java.util.ArrayList;
import java.util.List;

/** A parsed s-expression node with its source position: a symbol or a list. */
final class SExpr {
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

    /** Reads exactly one top-level expression; names are lower-cased (PDDL is case-insensitive). */
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

        SExpr expr() {
            char c = text.charAt(pos);
            int l = line, co = col;
            if (c == '(') {
                advance();
                List<SExpr> items = new ArrayList<>();
                while (true) {
                    skipBlank();
                    if (pos >= text.length()) {
                        throw new PddlParseException(source, l, co, "unbalanced '(': missing ')' before end of input");
                    }
                    if (text.charAt(pos) == ')') {
                        advance();
                        return new SExpr(null, items, l, co);
                    }
                    items.add(expr());
                }
            }
            if (c == ')') throw error("unexpected ')'");
            int start = pos;
            while (pos < text.length()) {
                char d = text.charAt(pos);
                if (Character.isWhitespace(d) || d == '(' || d == ')' || d == ';') break;
                advance();
            }
            return new SExpr(text.substring(start, pos).toLowerCase(java.util.Locale.ROOT), null, l, co);
        }
    }
}
