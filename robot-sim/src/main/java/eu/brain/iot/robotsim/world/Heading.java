package eu.brain.iot.robotsim.world;

/** The four directions a robot may face and move in; y grows downwards (row index). */
public enum Heading {
    N(0, -1), E(1, 0), S(0, 1), W(-1, 0);

    private final int dx;
    private final int dy;

    Heading(int dx, int dy) {
        this.dx = dx;
        this.dy = dy;
    }

    public int dx() {
        return dx;
    }

    public int dy() {
        return dy;
    }

    /** The heading that leads from one cell to a 4-neighbour cell. */
    static Heading between(int fromX, int fromY, int toX, int toY) {
        int dx = Integer.signum(toX - fromX);
        int dy = Integer.signum(toY - fromY);
        for (Heading h : values()) {
            if (h.dx == dx && h.dy == dy) {
                return h;
            }
        }
        throw new IllegalArgumentException("cells are not 4-neighbours");
    }
}
