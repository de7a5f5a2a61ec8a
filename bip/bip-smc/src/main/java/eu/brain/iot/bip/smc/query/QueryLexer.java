package eu.brain.iot.bip.smc.query;

import java.util.ArrayList;
import java.util.List;

import eu.brain.iot.bip.model.Pos;

/** Splits a query into tokens: numbers, names, operators; positions relative to where the query text starts. */
final class QueryLexer {

    enum Kind { NUMBER, NAME, SYMBOL, END }

    record Token(Kind kind, String text, Pos pos) {
        boolean is(String s) {
            return kind != Kind.NUMBER && text.equals(s);
        }
    }

    private static final String[] SYMBOLS = {"=?", ">=", "<=", "==", "!=", "=>", "->", "&&", "||", ">", "<", "!", "(",
        ")", "[", "]", "+", "-", "*", "/", "%", ":", ",", "=", "."};

    private QueryLexer() {
    }

    static List<Token> lex(String text, Pos origin) throws QueryException {
        List<Token> tokens = new ArrayList<>();
        int i = 0;
        while (i < text.length()) {
            char ch = text.charAt(i);
            Pos pos = new Pos(origin.file(), origin.line(), origin.column() + i);
            if (Character.isWhitespace(ch)) {
                i++;
            } else if (Character.isDigit(ch)) {
                int start = i;
                while (i < text.length() && (Character.isDigit(text.charAt(i)) || text.charAt(i) == '.'
                        && i + 1 < text.length() && Character.isDigit(text.charAt(i + 1)))) {
                    i++;
                }
                if (i < text.length() && (text.charAt(i) == 'e' || text.charAt(i) == 'E')) {
                    i++;
                    if (i < text.length() && (text.charAt(i) == '-' || text.charAt(i) == '+')) {
                        i++;
                    }
                    while (i < text.length() && Character.isDigit(text.charAt(i))) {
                        i++;
                    }
                }
                tokens.add(new Token(Kind.NUMBER, text.substring(start, i), pos));
            } else if (Character.isJavaIdentifierStart(ch)) {
                int start = i;
                while (i < text.length() && Character.isJavaIdentifierPart(text.charAt(i))) {
                    i++;
                }
                tokens.add(new Token(Kind.NAME, text.substring(start, i), pos));
            } else {
                String symbol = null;
                for (String s : SYMBOLS) {
                    if (text.startsWith(s, i)) {
                        symbol = s;
                        break;
                    }
                }
                if (symbol == null) {
                    throw new QueryException(pos, "unexpected character '" + ch + "' in query");
                }
                tokens.add(new Token(Kind.SYMBOL, symbol, pos));
                i += symbol.length();
            }
        }
        tokens.add(new Token(Kind.END, "end of query", new Pos(origin.file(), origin.line(), origin.column()
                + text.length())));
        return tokens;
    }
}
