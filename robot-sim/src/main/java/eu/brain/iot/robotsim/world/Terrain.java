package eu.brain.iot.robotsim.world;

/**
 * What a grid cell is made of. Area codes follow the paper's BIP constants
 * ({@code inDocking = 1}, {@code inUnload = 2}, {@code inStorage = 3}, {@code isDoor = 5}); a plain corridor is 0.
 */
public enum Terrain {
    WALL('#', -1),
    CORRIDOR('.', 0),
    DOCKING('d', 1),
    UNLOAD('u', 2),
    STORAGE('s', 3),
    DOOR('D', 5);

    private final char symbol;
    private final int area;

    Terrain(char symbol, int area) {
        this.symbol = symbol;
        this.area = area;
    }

    /** The character of this terrain in a map file. */
    public char symbol() {
        return symbol;
    }

    /** The paper's area code (0 corridor, 1 docking, 2 unload, 3 storage, 5 door, -1 wall). */
    public int area() {
        return area;
    }

    /** Whether a robot may ever stand here (a door only while open). */
    public boolean passable() {
        return this != WALL;
    }

    private static final Terrain[] VALUES = values();

    static Terrain ofOrdinal(int ordinal) {
        return VALUES[ordinal];
    }
}
