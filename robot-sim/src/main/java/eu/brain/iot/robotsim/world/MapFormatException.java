package eu.brain.iot.robotsim.world;

/** A map file that cannot be read; the message says where (source:line:col) and what to do. */
public final class MapFormatException extends Exception {
    private static final long serialVersionUID = 1L;

    public MapFormatException(String source, int line, int column, String problem) {
        super(source + ":" + line + ":" + column + ": " + problem);
    }
}
