package eu.brain.iot.bip.parser;

import java.util.ArrayList;
import java.util.List;

import eu.brain.iot.bip.model.Block;
import eu.brain.iot.bip.model.Expr;
import eu.brain.iot.bip.model.Expr.BinaryOp;
import eu.brain.iot.bip.model.Expr.UnaryOp;
import eu.brain.iot.bip.model.Pos;
import eu.brain.iot.bip.model.Stmt;
import eu.brain.iot.bip.parser.Token.Kind;

/**
 * Expressions and statements of the action language (C-like precedence). Dialect accepted besides BIP2:
 * {@code and}, {@code or}, {@code not} for {@code &&}, {@code ||}, {@code !}; a single {@code =} inside an
 * expression is read as {@code ==} with a warning (the paper's Listing 1 writes {@code positionX =1 and ...}).
 */
final class ActionParser {

    /** Words that end or structure an item and so can never be read as a name inside an expression. */
    static final java.util.Set<String> NOT_NAMES = java.util.Set.of("end", "package", "use", "extern", "const",
            "define", "component", "connector", "compound", "atom", "place", "places", "initial", "internal", "on",
            "from", "provided", "do", "priority", "if", "then", "else", "fi", "export");

    private final TokenCursor in;

    ActionParser(TokenCursor in) {
        this.in = in;
    }

    // ---------------------------------------------------------------- statements

    /** {@code { s1; s2; }} (the last {@code ;} may be left out). */
    Block block(String context) {
        Pos pos = in.pos();
        in.expect(Kind.LBRACE, context);
        List<Stmt> stmts = statements(true);
        in.expect(Kind.RBRACE, "to close the block opened at " + pos.line() + ":" + pos.column());
        return new Block(pos, stmts);
    }

    private List<Stmt> statements(boolean inBraces) {
        List<Stmt> stmts = new ArrayList<>();
        while (true) {
            while (in.accept(Kind.SEMI)) {
                // empty statements are allowed
            }
            if (in.atEnd() || (inBraces && in.at(Kind.RBRACE)) || (!inBraces && (in.atWord("else") || in.atWord("fi")))) {
                return stmts;
            }
            Stmt stmt = statement();
            stmts.add(stmt);
            if (!in.accept(Kind.SEMI) && !(stmt instanceof Stmt.If) && !(in.at(Kind.RBRACE) || in.atWord("else")
                    || in.atWord("fi"))) {
                throw in.fail("expected ';' after the statement, found " + in.peek().describe());
            }
        }
    }

    private Stmt statement() {
        Pos pos = in.pos();
        in.enter();
        try {
            if (in.acceptWord("if")) {
                Expr condition = expression();
                in.expectWord("then", "after the condition of 'if'");
                List<Stmt> then = statements(false);
                List<Stmt> otherwise = List.of();
                if (in.acceptWord("else")) {
                    otherwise = statements(false);
                }
                in.expectWord("fi", "to close the 'if' at " + pos.line() + ":" + pos.column());
                return new Stmt.If(pos, condition, then, otherwise);
            }
            if (!in.at(Kind.IDENT)) {
                throw in.fail("expected a statement (assignment, function call or 'if'), found " + in.peek().describe());
            }
            String first = in.next().text();
            String second = null;
            if (in.at(Kind.DOT) && in.peek(1).is(Kind.IDENT)) {
                in.next();
                second = in.next().text();
            }
            if (in.at(Kind.LPAREN)) {
                Expr.Call call = second == null ? new Expr.Call(pos, null, first, arguments())
                        : new Expr.Call(pos, first, second, arguments());
                return new Stmt.Call(pos, call);
            }
            Expr.Var target = second == null ? new Expr.Var(pos, null, first) : new Expr.Var(pos, first, second);
            boolean primed = in.accept(Kind.QUOTE);
            if (!in.accept(Kind.ASSIGN)) {
                throw in.fail("expected '=' or '(' after '" + target.text() + "' (a statement assigns or calls), found "
                        + in.peek().describe());
            }
            return new Stmt.Assign(pos, target, primed, expression());
        } finally {
            in.leave();
        }
    }

    // ---------------------------------------------------------------- expressions

    Expr expression() {
        return binary(1);
    }

    private Expr binary(int minPrec) {
        in.enter();
        try {
            Expr left = unary();
            while (true) {
                Token t = in.peek();
                BinaryOp op = binaryOp(t);
                if (op == null || op.prec < minPrec) {
                    return left;
                }
                if (t.is(Kind.ASSIGN)) {
                    in.warning(t.pos(), "'=' inside an expression is read as '=='; write '==' to compare");
                }
                in.next();
                Expr right = binary(op.prec + 1);
                left = new Expr.Binary(t.pos(), op, left, right);
            }
        } finally {
            in.leave();
        }
    }

    private static BinaryOp binaryOp(Token t) {
        return switch (t.kind()) {
            case BARBAR -> BinaryOp.OR;
            case AMPAMP -> BinaryOp.AND;
            case BAR -> BinaryOp.BIT_OR;
            case CARET -> BinaryOp.BIT_XOR;
            case AMP -> BinaryOp.BIT_AND;
            case EQ, ASSIGN -> BinaryOp.EQ;
            case NE -> BinaryOp.NE;
            case LT -> BinaryOp.LT;
            case LE -> BinaryOp.LE;
            case GT -> BinaryOp.GT;
            case GE -> BinaryOp.GE;
            case PLUS -> BinaryOp.ADD;
            case MINUS -> BinaryOp.SUB;
            case STAR -> BinaryOp.MUL;
            case SLASH -> BinaryOp.DIV;
            case PERCENT -> BinaryOp.MOD;
            case IDENT -> t.text().equals("and") ? BinaryOp.AND : t.text().equals("or") ? BinaryOp.OR : null;
            default -> null;
        };
    }

    private Expr unary() {
        Token t = in.peek();
        UnaryOp op = switch (t.kind()) {
            case BANG -> UnaryOp.NOT;
            case MINUS -> UnaryOp.NEG;
            case PLUS -> UnaryOp.PLUS;
            case TILDE -> UnaryOp.BIT_NOT;
            case IDENT -> t.text().equals("not") && startsOperand(in.peek(1)) ? UnaryOp.NOT : null;
            default -> null;
        };
        if (op == null) {
            return primary();
        }
        in.next();
        in.enter();
        try {
            return new Expr.Unary(t.pos(), op, unary());
        } finally {
            in.leave();
        }
    }

    private static boolean startsOperand(Token t) {
        return switch (t.kind()) {
            case IDENT -> !NOT_NAMES.contains(t.text());
            case INT, FLOAT, STRING, LPAREN, BANG, MINUS, PLUS, TILDE -> true;
            default -> false;
        };
    }

    private Expr primary() {
        Token t = in.peek();
        switch (t.kind()) {
            case INT -> {
                in.next();
                return new Expr.IntLit(t.pos(), parseInt(t));
            }
            case FLOAT -> {
                in.next();
                return new Expr.FloatLit(t.pos(), Double.parseDouble(t.text()));
            }
            case STRING -> {
                in.next();
                return new Expr.StringLit(t.pos(), t.text());
            }
            case LPAREN -> {
                in.next();
                Expr inner = expression();
                in.expect(Kind.RPAREN, "to close the parenthesis opened at " + t.pos().line() + ":" + t.pos().column());
                return inner;
            }
            case IDENT -> {
                if (NOT_NAMES.contains(t.text())) {
                    throw in.fail("expected an expression (a number, string, name, call or '('), found " + t.describe());
                }
                in.next();
                if (t.text().equals("true") || t.text().equals("false")) {
                    return new Expr.BoolLit(t.pos(), t.text().equals("true"));
                }
                String qualifier = null;
                String name = t.text();
                if (in.at(Kind.DOT) && in.peek(1).is(Kind.IDENT)) {
                    in.next();
                    qualifier = name;
                    name = in.next().text();
                }
                if (in.at(Kind.LPAREN)) {
                    return new Expr.Call(t.pos(), qualifier, name, arguments());
                }
                return new Expr.Var(t.pos(), qualifier, name);
            }
            default -> throw in.fail("expected an expression (a number, string, name, call or '('), found " + t.describe());
        }
    }

    private long parseInt(Token t) {
        String text = t.text();
        try {
            return text.startsWith("0x") || text.startsWith("0X") ? Long.parseLong(text.substring(2), 16)
                    : Long.parseLong(text);
        } catch (NumberFormatException e) {
            in.error(t.pos(), "integer " + text + " is too large");
            return 0;
        }
    }

    private List<Expr> arguments() {
        Pos open = in.pos();
        in.expect(Kind.LPAREN, "to start the arguments");
        List<Expr> args = new ArrayList<>();
        if (!in.at(Kind.RPAREN)) {
            args.add(expression());
            while (in.accept(Kind.COMMA)) {
                args.add(expression());
            }
        }
        in.expect(Kind.RPAREN, "to close the arguments opened at " + open.line() + ":" + open.column());
        return args;
    }
}
