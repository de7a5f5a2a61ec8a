package eu.brain.iot.robotsim.world;

/** A cart of shelves; either on the floor at (x, y) or lifted by a robot. Owned by the world's owner thread. */
public final class Cart {
    private final int index;
    private final String id;
    int x;
    int y;
    /** Index of the robot carrying it, -1 when on the floor. */
    int carriedBy = -1;

    Cart(int index, String id, int x, int y) {
        this.index = index;
        this.id = id;
        this.x = x;
        this.y = y;
    }

    public int index() {
        return index;
    }

    public String id() {
        return id;
    }

    public int x() {
        return x;
    }

    public int y() {
        return y;
    }

    public int carriedBy() {
        return carriedBy;
    }
}
