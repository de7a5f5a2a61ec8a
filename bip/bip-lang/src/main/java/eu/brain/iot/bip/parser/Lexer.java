package eu.brain.iot.bip.parser;

import java.util.ArrayList;
import java.util.List;

import eu.brain.iot.bip.diag.Diagnostics;
import eu.brain.iot.bip.model.Pos;
import eu.brain.iot.bip.parser.Token.Kind;

/**
 * Turns BIP source text into tokens, skipping {@code //} and {@code /* *}{@code /} comments. Bad characters and
 * unterminated strings or comments are reported and skipped, so the parser still sees the rest of the file.
 */
public final class Lexer {

    private final String file;
    private final String src;
    private final Diagnostics diagnostics;
    private final List<Token> tokens = new ArrayList<>();
    private int index;
    private int line = 1;
    private int lineStart;

    private Lexer(String file, String src, Diagnostics diagnostics) {
        this.file = file;
        this.src = src;
        this.diagnostics = diagnostics;
    }

    /** @return the tokens of {@code src}, ending with one {@link Kind#EOF} token */
    public static List<Token> tokenize(String file, String src, Diagnostics diagnostics) {
        Lexer lexer = new Lexer(file, src, diagnostics);
        lexer.run();
        return lexer.tokens;
    }

    private Pos pos(int at) {
        return new Pos(file, line, at - lineStart + 1);
    }

    private void run() {
        int n = src.length();
        while (true) {
            skipBlanksAndComments();
            if (index >= n) {
                tokens.add(new Token(Kind.EOF, "", pos(index)));
                return;
            }
            int start = index;
            char c = src.charAt(index);
            if (Character.isLetter(c) || c == '_') {
                while (index < n && (Character.isLetterOrDigit(src.charAt(index)) || src.charAt(index) == '_')) {
                    index++;
                }
                add(Kind.IDENT, start);
            } else if (Character.isDigit(c) || (c == '.' && index + 1 < n && Character.isDigit(src.charAt(index + 1))
                    && !afterName())) {
                number(start);
            } else if (c == '"') {
                string(start);
            } else {
                operator(start, c);
            }
        }
    }

    private void add(Kind kind, int start) {
        tokens.add(new Token(kind, src.substring(start, index), pos(start)));
    }

    private void skipBlanksAndComments() {
        int n = src.length();
        while (index < n) {
            char c = src.charAt(index);
            if (c == '\n') {
                index++;
                line++;
                lineStart = index;
            } else if (Character.isWhitespace(c) || c == '\uFEFF') {
                index++;
            } else if (c == '/' && index + 1 < n && src.charAt(index + 1) == '/') {
                while (index < n && src.charAt(index) != '\n') {
                    index++;
                }
            } else if (c == '/' && index + 1 < n && src.charAt(index + 1) == '*') {
                Pos start = pos(index);
                index += 2;
                boolean closed = false;
                while (index < n) {
                    if (src.charAt(index) == '*' && index + 1 < n && src.charAt(index + 1) == '/') {
                        index += 2;
                        closed = true;
                        break;
                    }
                    if (src.charAt(index) == '\n') {
                        line++;
                        lineStart = index + 1;
                    }
                    index++;
                }
                if (!closed) {
                    diagnostics.error(start, "comment '/*' is never closed: add '*/'");
                }
            } else {
                return;
            }
        }
    }

    /** @return whether the previous token ends a name or a value (then a '.' is a qualifier dot, not a number) */
    private boolean afterName() {
        if (tokens.isEmpty()) {
            return false;
        }
        Token last = tokens.get(tokens.size() - 1);
        return last.is(Kind.IDENT) || last.is(Kind.RPAREN) || last.is(Kind.INT) || last.is(Kind.FLOAT);
    }

    private void number(int start) {
        int n = src.length();
        boolean isFloat = false;
        if (src.charAt(index) == '.') {
            index++;
            while (index < n && Character.isDigit(src.charAt(index))) {
                index++;
            }
            isFloat = true;
            exponentAndEnd(start, isFloat);
            return;
        }
        if (src.charAt(index) == '0' && index + 1 < n && (src.charAt(index + 1) == 'x' || src.charAt(index + 1) == 'X')) {
            index += 2;
            while (index < n && Character.digit(src.charAt(index), 16) >= 0) {
                index++;
            }
            add(Kind.INT, start);
            return;
        }
        while (index < n && Character.isDigit(src.charAt(index))) {
            index++;
        }
        if (index + 1 < n && src.charAt(index) == '.' && Character.isDigit(src.charAt(index + 1))) {
            isFloat = true;
            index++;
            while (index < n && Character.isDigit(src.charAt(index))) {
                index++;
            }
        }
        exponentAndEnd(start, isFloat);
    }

    private void exponentAndEnd(int start, boolean isFloat) {
        int n = src.length();
        if (index < n && (src.charAt(index) == 'e' || src.charAt(index) == 'E')) {
            int save = index;
            index++;
            if (index < n && (src.charAt(index) == '+' || src.charAt(index) == '-')) {
                index++;
            }
            if (index < n && Character.isDigit(src.charAt(index))) {
                isFloat = true;
                while (index < n && Character.isDigit(src.charAt(index))) {
                    index++;
                }
            } else {
                index = save;
            }
        }
        add(isFloat ? Kind.FLOAT : Kind.INT, start);
    }

    private void string(int start) {
        int n = src.length();
        StringBuilder value = new StringBuilder();
        index++;
        while (index < n && src.charAt(index) != '"' && src.charAt(index) != '\n') {
            char c = src.charAt(index);
            if (c == '\\' && index + 1 < n && src.charAt(index + 1) != '\n') {
                char e = src.charAt(index + 1);
                value.append(switch (e) {
                    case 'n' -> '\n';
                    case 't' -> '\t';
                    case 'r' -> '\r';
                    case '0' -> '\0';
                    default -> e;
                });
                index += 2;
            } else {
                value.append(c);
                index++;
            }
        }
        if (index < n && src.charAt(index) == '"') {
            index++;
        } else {
            diagnostics.error(pos(start), "string is not closed on its line: add '\"'");
        }
        tokens.add(new Token(Kind.STRING, value.toString(), pos(start)));
    }

    private void operator(int start, char c) {
        char next = index + 1 < src.length() ? src.charAt(index + 1) : '\0';
        Kind kind = switch (c) {
            case '(' -> Kind.LPAREN;
            case ')' -> Kind.RPAREN;
            case '{' -> Kind.LBRACE;
            case '}' -> Kind.RBRACE;
            case ',' -> Kind.COMMA;
            case ';' -> Kind.SEMI;
            case '.' -> Kind.DOT;
            case ':' -> Kind.COLON;
            case '\'', '\u2019' -> Kind.QUOTE;
            case '@' -> Kind.AT;
            case '=' -> next == '=' ? Kind.EQ : Kind.ASSIGN;
            case '!' -> next == '=' ? Kind.NE : Kind.BANG;
            case '<' -> next == '=' ? Kind.LE : Kind.LT;
            case '>' -> next == '=' ? Kind.GE : Kind.GT;
            case '+' -> Kind.PLUS;
            case '-' -> Kind.MINUS;
            case '*' -> Kind.STAR;
            case '/' -> Kind.SLASH;
            case '%' -> Kind.PERCENT;
            case '~' -> Kind.TILDE;
            case '&' -> next == '&' ? Kind.AMPAMP : Kind.AMP;
            case '|' -> next == '|' ? Kind.BARBAR : Kind.BAR;
            case '^' -> Kind.CARET;
            default -> null;
        };
        if (kind == null) {
            diagnostics.error(pos(start), "unexpected character '" + printable(c) + "': not part of the BIP language");
            index++;
            return;
        }
        index += kind.symbol.length();
        tokens.add(new Token(kind, kind.symbol, pos(start)));
    }

    private static String printable(char c) {
        return Character.isISOControl(c) ? String.format("\\u%04x", (int) c) : String.valueOf(c);
    }
}
