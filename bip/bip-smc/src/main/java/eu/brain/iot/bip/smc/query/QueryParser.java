package eu.brain.iot.bip.smc.query;

import java.util.ArrayList;
import java.util.List;

import eu.brain.iot.bip.check.Type;
import eu.brain.iot.bip.model.Expr.BinaryOp;
import eu.brain.iot.bip.model.Expr.UnaryOp;
import eu.brain.iot.bip.model.Pos;
import eu.brain.iot.bip.smc.query.QueryLexer.Kind;
import eu.brain.iot.bip.smc.query.QueryLexer.Token;

/**
 * Parses and resolves a PBLTL query against a system (see bip/README, "Queries"). Precedence, loosest first:
 * {@code =>} (right), {@code ||}, {@code &&}, {@code U<=t} (right), then the prefix operators {@code ! X F<=t G<=t},
 * then comparisons and arithmetic. Stops at the first error.
 */
public final class QueryParser {

    private final List<Token> tokens;
    private final Names names;
    private final List<Term> propositions = new ArrayList<>();
    private final List<Query.Sweep> sweeps = new ArrayList<>();
    private int at;

    private QueryParser(List<Token> tokens, Names names) {
        this.tokens = tokens;
        this.names = names;
    }

    /**
     * @param origin where the text starts (file, line, column), for messages
     * @param names the system's components, data, places and constants
     */
    public static Query parse(String name, String text, Pos origin, Names names, String justification)
            throws QueryException {
        QueryParser p = new QueryParser(QueryLexer.lex(text, origin), names);
        return p.query(name == null ? text.strip() : name, text.strip(), origin, justification);
    }

    private Token peek() {
        return tokens.get(at);
    }

    private Token peek(int ahead) {
        return tokens.get(Math.min(at + ahead, tokens.size() - 1));
    }

    private Token next() {
        Token t = tokens.get(at);
        if (t.kind() != Kind.END) {
            at++;
        }
        return t;
    }

    private boolean accept(String s) {
        if (peek().is(s)) {
            at++;
            return true;
        }
        return false;
    }

    private Token expect(String s, String what) throws QueryException {
        if (!peek().is(s)) {
            throw error(peek(), "expected " + what + ", found " + describe(peek()));
        }
        return next();
    }

    private static String describe(Token t) {
        return t.kind() == Kind.END ? "the end of the query" : "'" + t.text() + "'";
    }

    private static QueryException error(Token t, String message) {
        return new QueryException(t.pos(), message);
    }

    private Query query(String name, String text, Pos origin, String justification) throws QueryException {
        int head = at;
        int depth = 0;
        for (int i = 0; i < tokens.size(); i++) {
            Token t = tokens.get(i);
            depth += t.is("[") ? 1 : t.is("]") ? -1 : 0;
            if (depth == 0 && t.kind() == Kind.NAME && t.text().equals("for") && i > 0 && tokens.get(i - 1).is("]")) {
                at = i + 1;
                sweeps();
                if (peek().kind() != Kind.END) {
                    throw error(peek(), "expected ',' and another sweep, found " + describe(peek()));
                }
                tokens.set(i, new Token(Kind.END, "end of query", t.pos()));
                break;
            }
        }
        at = head;
        Token p = next();
        if (!(p.kind() == Kind.NAME && p.text().equals("P"))) {
            throw error(p, "a query starts with P=?, P>=θ or P<=θ, found " + describe(p));
        }
        Query.Kind kind;
        double threshold = Double.NaN;
        if (accept("=?")) {
            kind = Query.Kind.ESTIMATE;
        } else if (peek().is(">=") || peek().is(">") || peek().is("<=") || peek().is("<")) {
            kind = next().text().startsWith(">") ? Query.Kind.AT_LEAST : Query.Kind.AT_MOST;
            Token t = next();
            if (t.kind() != Kind.NUMBER) {
                throw error(t, "expected a probability after the comparison, found " + describe(t));
            }
            threshold = Double.parseDouble(t.text());
            if (threshold < 0 || threshold > 1) {
                throw error(t, "the threshold " + t.text() + " is not a probability (0 to 1)");
            }
        } else {
            throw error(peek(), "expected =?, >=, >, <= or < after P, found " + describe(peek()));
        }
        expect("[", "'[' before the formula");
        Formula f = implies();
        expect("]", "']' after the formula (or an operator)");
        if (peek().kind() != Kind.END) {
            throw error(peek(), "expected the end of the query or 'for x = from:to:step', found " + describe(peek()));
        }
        return new Query(name, text, kind, threshold, f, propositions, sweeps, origin, justification);
    }

    private void sweeps() throws QueryException {
        do {
            Token n = next();
            if (n.kind() != Kind.NAME) {
                throw error(n, "expected a parameter name, found " + describe(n));
            }
            if (sweeps.stream().anyMatch(s -> s.name().equals(n.text()))) {
                throw error(n, "parameter " + n.text() + " is swept twice");
            }
            expect("=", "'=' after the parameter name");
            Token[] parts = {null, null, null};
            double[] v = new double[3];
            for (int i = 0; i < 3; i++) {
                if (i > 0) {
                    expect(":", "':' (from:to:step)");
                }
                boolean negative = accept("-");
                parts[i] = next();
                if (parts[i].kind() != Kind.NUMBER) {
                    throw error(parts[i], "expected a number (from:to:step), found " + describe(parts[i]));
                }
                v[i] = (negative ? -1 : 1) * Double.parseDouble(parts[i].text());
            }
            if (v[2] <= 0 || v[1] < v[0]) {
                throw error(parts[2], "a sweep needs from <= to and a positive step");
            }
            boolean integral = v[0] == Math.rint(v[0]) && v[2] == Math.rint(v[2]);
            sweeps.add(new Query.Sweep(n.text(), v[0], v[1], v[2], integral));
        } while (accept(","));
    }

    private Formula implies() throws QueryException {
        Formula left = or();
        if (accept("=>") || accept("->")) {
            return new Formula.Or(new Formula.Not(left), implies());
        }
        return left;
    }

    private Formula or() throws QueryException {
        Formula f = and();
        while (accept("||") || acceptWord("or")) {
            f = new Formula.Or(f, and());
        }
        return f;
    }

    private Formula and() throws QueryException {
        Formula f = until();
        while (accept("&&") || acceptWord("and")) {
            f = new Formula.And(f, until());
        }
        return f;
    }

    private boolean acceptWord(String w) {
        if (peek().kind() == Kind.NAME && peek().text().equals(w)) {
            at++;
            return true;
        }
        return false;
    }

    private boolean temporal(String op) {
        return peek().kind() == Kind.NAME && peek().text().equals(op) && peek(1).is("<=");
    }

    private Formula until() throws QueryException {
        Formula left = prefix();
        if (temporal("U")) {
            next();
            next();
            Formula.Bound b = bound();
            return new Formula.Until(left, until(), b);
        }
        return left;
    }

    private Formula.Bound bound() throws QueryException {
        Token t = next();
        if (t.kind() == Kind.NUMBER && t.text().matches("\\d+")) {
            return new Formula.Bound(Integer.parseInt(t.text()), -1);
        }
        if (t.kind() == Kind.NAME) {
            for (int i = 0; i < sweeps.size(); i++) {
                if (sweeps.get(i).name().equals(t.text()) && sweeps.get(i).integral() && sweeps.get(i).from() >= 0) {
                    return new Formula.Bound(0, i);
                }
            }
        }
        throw error(t, "expected a step bound (a whole number, or a swept parameter with whole values), found "
                + describe(t));
    }

    private Formula prefix() throws QueryException {
        if (accept("!") || acceptWord("not")) {
            return new Formula.Not(prefix());
        }
        if (peek().kind() == Kind.NAME && peek().text().equals("X") && !peek(1).is(".") && !isOperator(peek(1))) {
            next();
            return new Formula.Next(prefix());
        }
        if (temporal("F") || temporal("G")) {
            boolean g = next().text().equals("G");
            next();
            Formula.Bound b = bound();
            Formula f = prefix();
            return g ? new Formula.Not(new Formula.Until(new Formula.Const(true), new Formula.Not(f), b))
                    : new Formula.Until(new Formula.Const(true), f, b);
        }
        if (peek().is("(")) {
            int save = at;
            next();
            try {
                Formula f = implies();
                expect(")", "')'");
                if (!isOperator(peek())) {
                    return f;
                }
            } catch (QueryException e) {
                // not a parenthesised formula: an arithmetic or comparison expression
            }
            at = save;
        }
        if (acceptWord("true")) {
            return new Formula.Const(true);
        }
        if (acceptWord("false")) {
            return new Formula.Const(false);
        }
        Token start = peek();
        Term t = new TermParser(this).comparison();
        if (t.type().kind() != Type.Kind.BOOL) {
            throw error(start, "expected a condition (a comparison, 'C at PLACE' or a bool datum), found an "
                    + t.type() + " expression");
        }
        propositions.add(t);
        return new Formula.Ap(propositions.size() - 1);
    }

    private static boolean isOperator(Token t) {
        return t.kind() == Kind.SYMBOL && List.of("==", "!=", "<", "<=", ">", ">=", "+", "-", "*", "/", "%")
                .contains(t.text());
    }

    /** Arithmetic and comparisons over component data (a nested class: it shares the token cursor). */
    static final class TermParser {
        private final QueryParser q;

        TermParser(QueryParser q) {
            this.q = q;
        }

        Term comparison() throws QueryException {
            Term left = additive();
            Token op = q.peek();
            BinaryOp bop = switch (op.kind() == Kind.SYMBOL ? op.text() : "") {
                case "==" -> BinaryOp.EQ;
                case "!=" -> BinaryOp.NE;
                case "<" -> BinaryOp.LT;
                case "<=" -> BinaryOp.LE;
                case ">" -> BinaryOp.GT;
                case ">=" -> BinaryOp.GE;
                default -> null;
            };
            if (bop == null) {
                return left;
            }
            q.next();
            Term right = additive();
            boolean numeric = left.type().numeric() && right.type().numeric();
            boolean same = left.type().equals(right.type()) && (bop == BinaryOp.EQ || bop == BinaryOp.NE);
            if (!numeric && !same) {
                throw error(op, "cannot compare " + left.type() + " with " + right.type() + " using " + op.text());
            }
            return new Term.Binary(bop, left, right, Type.BOOL);
        }

        private Term additive() throws QueryException {
            Term t = multiplicative();
            while (q.peek().is("+") || q.peek().is("-")) {
                Token op = q.next();
                t = arithmetic(op, op.text().equals("+") ? BinaryOp.ADD : BinaryOp.SUB, t, multiplicative());
            }
            return t;
        }

        private Term multiplicative() throws QueryException {
            Term t = unary();
            while (q.peek().is("*") || q.peek().is("/") || q.peek().is("%")) {
                Token op = q.next();
                BinaryOp b = op.text().equals("*") ? BinaryOp.MUL : op.text().equals("/") ? BinaryOp.DIV : BinaryOp.MOD;
                t = arithmetic(op, b, t, unary());
            }
            return t;
        }

        private static Term arithmetic(Token op, BinaryOp b, Term l, Term r) throws QueryException {
            if (!l.type().numeric() || !r.type().numeric()) {
                throw error(op, "operator " + op.text() + " needs numbers, found " + l.type() + " and " + r.type());
            }
            Type t = l.type().kind() == Type.Kind.INT && r.type().kind() == Type.Kind.INT ? Type.INT : Type.FLOAT;
            return new Term.Binary(b, l, r, t);
        }

        private Term unary() throws QueryException {
            Token t = q.peek();
            if (q.accept("-")) {
                Term operand = unary();
                if (!operand.type().numeric()) {
                    throw error(t, "'-' needs a number, found " + operand.type());
                }
                return new Term.Unary(UnaryOp.NEG, operand, operand.type());
            }
            if (q.accept("(")) {
                Term inner = comparison();
                q.expect(")", "')'");
                return inner;
            }
            Token n = q.next();
            if (n.kind() == Kind.NUMBER) {
                return n.text().matches("\\d+") ? new Term.Lit(Integer.parseInt(n.text()), Type.INT)
                        : new Term.Lit(Double.parseDouble(n.text()), Type.FLOAT);
            }
            if (n.kind() != Kind.NAME) {
                throw error(n, "expected a number, a parameter or component.data, found " + describe(n));
            }
            List<Token> parts = new ArrayList<>(List.of(n));
            while (q.peek().is(".") && q.peek(1).kind() == Kind.NAME) {
                q.next();
                parts.add(q.next());
            }
            if (q.peek().kind() == Kind.NAME && q.peek().text().equals("at")) {
                q.next();
                Token place = q.next();
                if (place.kind() != Kind.NAME) {
                    throw error(place, "expected a place after 'at', found " + describe(place));
                }
                return q.names.at(parts, place);
            }
            return q.names.value(parts, q.sweeps);
        }
    }
}
