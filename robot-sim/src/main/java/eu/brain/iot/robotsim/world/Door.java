package eu.brain.iot.robotsim.world;

/** An automatic door on one cell. Owned by the world's owner thread. */
public final class Door {
    private final int index;
    private final String id;
    private final int x;
    private final int y;
    private final int openSteps;
    private DoorState state = DoorState.CLOSED;
    private int stepsLeft;
    private long openings;

    Door(int index, String id, int x, int y, int openSteps) {
        this.index = index;
        this.id = id;
        this.x = x;
        this.y = y;
        this.openSteps = openSteps;
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

    public DoorState state() {
        return state;
    }

    /** Steps still needed to finish opening (0 unless OPENING). */
    public int stepsLeft() {
        return stepsLeft;
    }

    /** Times the door began to open: closed to opening (or open at once), or closing back to open. */
    public long openings() {
        return openings;
    }

    public boolean passable() {
        return state == DoorState.OPEN;
    }

    /** The command {@code data: 1.0}: starts opening (a door that takes 0 steps opens at once). */
    void commandOpen() {
        switch (state) {
            case CLOSED -> {
                stepsLeft = openSteps;
                state = openSteps == 0 ? DoorState.OPEN : DoorState.OPENING;
                openings++;
            }
            case CLOSING -> {
                state = DoorState.OPEN;
                openings++;
            }
            default -> {
                // already open or opening
            }
        }
    }

    /** The command {@code data: 0.0}: closes now, or as soon as no robot stands in the doorway. */
    void commandClose(boolean robotInDoorway) {
        switch (state) {
            case OPENING -> {
                state = DoorState.CLOSED;
                stepsLeft = 0;
            }
            case OPEN -> state = robotInDoorway ? DoorState.CLOSING : DoorState.CLOSED;
            default -> {
                // already closed or closing
            }
        }
    }

    /** Advances one simulation step. */
    void tick(boolean robotInDoorway) {
        if (state == DoorState.OPENING && --stepsLeft <= 0) {
            stepsLeft = 0;
            state = DoorState.OPEN;
        } else if (state == DoorState.CLOSING && !robotInDoorway) {
            state = DoorState.CLOSED;
        }
    }
}
