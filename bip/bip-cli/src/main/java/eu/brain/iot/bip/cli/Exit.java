package eu.brain.iot.bip.cli;

/** The exit codes of {@code bip}. */
final class Exit {

    /** No error (and, for {@code smc}, no requirement refuted). */
    static final int OK = 0;
    /** The models, the queries or the requirements file have errors, or a requirement is refuted. */
    static final int PROBLEMS = 1;
    /** A bad command line: the message and the usage are printed. */
    static final int USAGE = 2;
    /** An internal failure or an interruption, reported in one line. */
    static final int INTERNAL = 3;

    private Exit() {
    }
}
