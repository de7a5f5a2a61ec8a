package eu.brain.iot.bip.parser;

import eu.brain.iot.bip.model.Pos;

/**
 * One token. Words are all {@link Kind#IDENT}: BIP keywords are recognised by the parser where they can occur, so a
 * model may use {@code up} or {@code unit} as a name where no keyword fits.
 */
public record Token(Kind kind, String text, Pos pos) {

    public enum Kind {
        IDENT, INT, FLOAT, STRING, LPAREN("("), RPAREN(")"), LBRACE("{"), RBRACE("}"), COMMA(","), SEMI(";"), DOT("."),
        COLON(":"), QUOTE("'"), AT("@"), ASSIGN("="), EQ("=="), NE("!="), LT("<"), LE("<="), GT(">"), GE(">="),
        PLUS("+"), MINUS("-"), STAR("*"), SLASH("/"), PERCENT("%"), BANG("!"), TILDE("~"), AMP("&"), AMPAMP("&&"),
        BAR("|"), BARBAR("||"), CARET("^"), EOF;

        public final String symbol;

        Kind() {
            this.symbol = null;
        }

        Kind(String symbol) {
            this.symbol = symbol;
        }
    }

    public boolean is(Kind k) {
        return kind == k;
    }

    /** @return whether this is the word {@code word} */
    public boolean isWord(String word) {
        return kind == Kind.IDENT && text.equals(word);
    }

    /** @return the token as a message shows it: {@code 'text'} or {@code end of file} */
    public String describe() {
        return switch (kind) {
            case EOF -> "end of file";
            case STRING -> "string \"" + shorten(text) + "\"";
            default -> "'" + shorten(text) + "'";
        };
    }

    private static String shorten(String s) {
        return s.length() > 40 ? s.substring(0, 37) + "..." : s;
    }
}
