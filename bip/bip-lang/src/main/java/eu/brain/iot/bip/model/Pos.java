package eu.brain.iot.bip.model;

/**
 * Where a model element was written: file, line and column (both 1-based).
 * <p>
 * Positions are metadata, not meaning: every {@code Pos} equals every other one (and all hash alike), so two
 * model trees are equal when they say the same thing, wherever it was written. This is what makes the
 * print-then-parse round trip comparable with {@code equals}. Compare positions with {@link #sameAs(Pos)}.
 */
public final class Pos {

    /** For elements built in code rather than parsed. */
    public static final Pos NONE = new Pos("<none>", 0, 0);

    private final String file;
    private final int line;
    private final int column;

    public Pos(String file, int line, int column) {
        this.file = file;
        this.line = line;
        this.column = column;
    }

    public String file() {
        return file;
    }

    public int line() {
        return line;
    }

    public int column() {
        return column;
    }

    /** @return whether both name the same place (unlike {@link #equals}, which ignores positions) */
    public boolean sameAs(Pos other) {
        return other != null && file.equals(other.file) && line == other.line && column == other.column;
    }

    @Override
    public boolean equals(Object other) {
        return other instanceof Pos;
    }

    @Override
    public int hashCode() {
        return 0;
    }

    @Override
    public String toString() {
        return file + ":" + line + ":" + column;
    }
}
