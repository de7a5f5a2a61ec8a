package eu.brain.iot.bip.model;

import java.util.List;

/** An expression of the action language. */
public sealed interface Expr {

    Pos pos();

    record IntLit(Pos pos, long value) implements Expr {
    }

    record FloatLit(Pos pos, double value) implements Expr {
    }

    record BoolLit(Pos pos, boolean value) implements Expr {
    }

    /** The value after escapes are resolved. */
    record StringLit(Pos pos, String value) implements Expr {
    }

    /**
     * A name: data, parameter or constant ({@code qualifier} null), or {@code port.data} in connectors and
     * {@code component.data} in compound priorities.
     */
    record Var(Pos pos, String qualifier, String name) implements Expr {
        public String text() {
            return qualifier == null ? name : qualifier + "." + name;
        }
    }

    /** {@code f(args)} or a qualified call {@code Map.getDockingX()} (the BRAIN-IoT dialect); qualifier may be null. */
    record Call(Pos pos, String qualifier, String name, List<Expr> args) implements Expr {
        public Call {
            args = List.copyOf(args);
        }

        public String text() {
            return qualifier == null ? name : qualifier + "." + name;
        }
    }

    record Unary(Pos pos, UnaryOp op, Expr operand) implements Expr {
    }

    record Binary(Pos pos, BinaryOp op, Expr left, Expr right) implements Expr {
    }

    enum UnaryOp {
        NOT("!"), NEG("-"), PLUS("+"), BIT_NOT("~");

        public final String symbol;

        UnaryOp(String symbol) {
            this.symbol = symbol;
        }
    }

    /** Binary operators with C precedence ({@code prec}: higher binds tighter). */
    enum BinaryOp {
        OR("||", 1), AND("&&", 2), BIT_OR("|", 3), BIT_XOR("^", 4), BIT_AND("&", 5), EQ("==", 6), NE("!=", 6),
        LT("<", 7), LE("<=", 7), GT(">", 7), GE(">=", 7), ADD("+", 8), SUB("-", 8), MUL("*", 9), DIV("/", 9),
        MOD("%", 9);

        public final String symbol;
        public final int prec;

        BinaryOp(String symbol, int prec) {
            this.symbol = symbol;
            this.prec = prec;
        }

        public boolean comparison() {
            return prec == 6 || prec == 7;
        }

        public boolean logical() {
            return this == OR || this == AND;
        }

        public boolean arithmetic() {
            return prec >= 8;
        }

        public boolean bitwise() {
            return this == BIT_OR || this == BIT_XOR || this == BIT_AND;
        }
    }
}
