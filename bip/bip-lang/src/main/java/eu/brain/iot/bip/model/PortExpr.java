package eu.brain.iot.bip.model;

import java.util.List;

/** The port expression after {@code define}: port names and parenthesised groups, each a trigger when quoted. */
public sealed interface PortExpr {

    Pos pos();

    boolean trigger();

    /** A connector port parameter, {@code p} or {@code p'}. */
    record Ref(Pos pos, String port, boolean trigger) implements PortExpr {
    }

    /** {@code (e1 e2 ...)} or {@code (e1 e2 ...)'}; the whole define is a non-trigger group. */
    record Group(Pos pos, List<PortExpr> items, boolean trigger) implements PortExpr {
        public Group {
            items = List.copyOf(items);
        }
    }
}
