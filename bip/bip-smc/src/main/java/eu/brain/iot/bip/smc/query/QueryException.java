package eu.brain.iot.bip.smc.query;

import eu.brain.iot.bip.model.Pos;

/** A query that cannot be parsed or resolved: where, and what is wrong (naming what exists). */
public final class QueryException extends Exception {
    private static final long serialVersionUID = 1L;
    private final transient Pos pos;

    public QueryException(Pos pos, String message) {
        super(message);
        this.pos = pos;
    }

    public Pos pos() {
        return pos;
    }

    /** @return {@code file:line:col: error: message} */
    @Override
    public String toString() {
        return pos.file() + ":" + pos.line() + ":" + pos.column() + ": error: " + getMessage();
    }
}
