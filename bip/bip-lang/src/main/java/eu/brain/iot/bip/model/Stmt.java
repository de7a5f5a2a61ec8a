package eu.brain.iot.bip.model;

import java.util.List;

/** A statement of the action language: assignment, function call, or {@code if ... then ... else ... fi}. */
public sealed interface Stmt {

    Pos pos();

    /**
     * {@code x = e;}, {@code p.x = e;} in connectors, or {@code c' = e;} (a clock's rate, timed BIP) when
     * {@code primed}.
     */
    record Assign(Pos pos, Expr.Var target, boolean primed, Expr value) implements Stmt {
    }

    /** {@code f(a, b);} or {@code Printer.print(txt);}. */
    record Call(Pos pos, Expr.Call call) implements Stmt {
    }

    /** {@code if (c) then s1; else s2; fi}; {@code otherwise} is empty when there is no else part. */
    record If(Pos pos, Expr condition, List<Stmt> then, List<Stmt> otherwise) implements Stmt {
        public If {
            then = List.copyOf(then);
            otherwise = List.copyOf(otherwise);
        }
    }
}
