package eu.brain.iot.bip.parser;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;

import eu.brain.iot.bip.diag.Diagnostics;
import eu.brain.iot.bip.model.Pos;
import eu.brain.iot.bip.parser.Token.Kind;

/**
 * The parsers' shared position in the token list, with the error handling they all use: a syntax error is reported
 * once and then thrown as {@link SyntaxError}, which the enclosing item parser catches to skip ahead to the next
 * place where parsing can resume (see {@link #syncTo}). Owned by one parse run on one thread.
 */
final class TokenCursor {

    /** Thrown after a syntax error has been reported; carries no stack trace (it is control flow, not a bug). */
    static final class SyntaxError extends RuntimeException {
        private static final long serialVersionUID = 1L;

        SyntaxError() {
            super(null, null, false, false);
        }
    }

    /** More than this many errors in one file are counted but not listed. */
    static final int MAX_ERRORS = 100;
    /** Deeper nesting than this is reported instead of risking the stack. */
    static final int MAX_DEPTH = 150;

    private final List<Token> tokens;
    private final Diagnostics diagnostics;
    private int index;
    private int lastErrorIndex = -1;
    private int errors;
    private int depth;

    TokenCursor(List<Token> tokens, Diagnostics diagnostics) {
        this.tokens = tokens;
        this.diagnostics = diagnostics;
    }

    Token peek() {
        return tokens.get(index);
    }

    Token peek(int ahead) {
        return tokens.get(Math.min(index + ahead, tokens.size() - 1));
    }

    Pos pos() {
        return peek().pos();
    }

    /** @return the index of the current token, to tell later whether an item consumed anything */
    int mark() {
        return index;
    }

    boolean atEnd() {
        return peek().is(Kind.EOF);
    }

    Token next() {
        Token t = tokens.get(index);
        if (!t.is(Kind.EOF)) {
            index++;
        }
        return t;
    }

    boolean at(Kind kind) {
        return peek().is(kind);
    }

    boolean atWord(String word) {
        return peek().isWord(word);
    }

    boolean atWord(String word, String then) {
        return peek().isWord(word) && peek(1).isWord(then);
    }

    boolean atAnyWord(Set<String> words) {
        return peek().is(Kind.IDENT) && words.contains(peek().text());
    }

    boolean accept(Kind kind) {
        if (at(kind)) {
            next();
            return true;
        }
        return false;
    }

    boolean acceptWord(String word) {
        if (atWord(word)) {
            next();
            return true;
        }
        return false;
    }

    Token expect(Kind kind, String context) {
        if (at(kind)) {
            return next();
        }
        String what = kind.symbol != null ? "'" + kind.symbol + "'"
                : "a " + kind.name().toLowerCase(java.util.Locale.ROOT);
        throw fail("expected " + what + " " + context + ", found " + peek().describe());
    }

    void expectWord(String word, String context) {
        if (!acceptWord(word)) {
            throw fail("expected '" + word + "' " + context + ", found " + peek().describe());
        }
    }

    /** Reads a name; {@code what} says what kind of name, e.g. "a place name after 'from'". */
    String ident(String what) {
        if (at(Kind.IDENT)) {
            return next().text();
        }
        throw fail("expected " + what + ", found " + peek().describe());
    }

    /** Reads {@code a.b.c}. */
    String qualifiedName(String what) {
        StringBuilder name = new StringBuilder(ident(what));
        while (at(Kind.DOT) && peek(1).is(Kind.IDENT)) {
            next();
            name.append('.').append(next().text());
        }
        return name.toString();
    }

    /** Reads {@code A, B, C}. */
    List<String> identList(String what) {
        List<String> names = new ArrayList<>();
        names.add(ident(what));
        while (accept(Kind.COMMA)) {
            names.add(ident(what));
        }
        return names;
    }

    /** Reports an error at the current token (once per token) and returns the exception to throw. */
    SyntaxError fail(String message) {
        error(peek().pos(), message);
        return new SyntaxError();
    }

    void error(Pos pos, String message) {
        if (index == lastErrorIndex) {
            return;
        }
        lastErrorIndex = index;
        errors++;
        if (errors <= MAX_ERRORS) {
            diagnostics.error(pos, message);
        } else if (errors == MAX_ERRORS + 1) {
            diagnostics.error(pos, "too many syntax errors in this file; later ones are not listed");
        }
    }

    void warning(Pos pos, String message) {
        diagnostics.warning(pos, message);
    }

    void enter() {
        if (++depth > MAX_DEPTH) {
            depth = 0;
            throw fail("nesting deeper than " + MAX_DEPTH + " levels: simplify this expression or statement");
        }
    }

    void leave() {
        depth = Math.max(0, depth - 1);
    }

    void resetDepth() {
        depth = 0;
    }

    /**
     * Skips tokens until one of {@code words} (as a word), a closing brace matching nothing skipped, or the end;
     * braces and parentheses skipped over are balanced so that words inside blocks are not mistaken for items.
     * Always moves at least one token, so a parser loop cannot get stuck.
     */
    void syncTo(Set<String> words) {
        syncUntil(() -> peek().is(Kind.IDENT) && words.contains(peek().text()), words.contains("@"));
    }

    /** Like {@link #syncTo(Set)}, stopping where {@code stop} holds (or at an annotation when {@code atAnnotation}). */
    void syncUntil(java.util.function.BooleanSupplier stop, boolean atAnnotation) {
        syncUntil(stop, atAnnotation, index);
    }

    /**
     * Like {@link #syncUntil(java.util.function.BooleanSupplier, boolean)}; when the failed item (which began at
     * {@code itemStart}) consumed tokens, the current token may itself be where parsing resumes (e.g. the 'atom'
     * after a port type missing its ')').
     */
    void syncUntil(java.util.function.BooleanSupplier stop, boolean atAnnotation, int itemStart) {
        int start = index > itemStart ? index - 1 : index;
        int nesting = 0;
        while (!atEnd()) {
            Token t = peek();
            if (nesting == 0 && index > start && stop.getAsBoolean()) {
                return;
            }
            if (t.is(Kind.LBRACE)) {
                nesting++;
            } else if (t.is(Kind.RBRACE)) {
                if (nesting == 0 && index > start) {
                    return;
                }
                nesting = Math.max(0, nesting - 1);
            } else if (t.is(Kind.AT) && nesting == 0 && index > start && atAnnotation) {
                return;
            }
            next();
        }
    }
}
