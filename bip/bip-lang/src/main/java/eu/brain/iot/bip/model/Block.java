package eu.brain.iot.bip.model;

import java.util.List;

/** {@code { statement; ... }}: the actions of a transition or a connector transfer function. */
public record Block(Pos pos, List<Stmt> stmts) {

    public Block {
        stmts = List.copyOf(stmts);
    }
}
