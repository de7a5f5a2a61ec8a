package eu.brain.iot.bis.api;

/**
 * Why an install or uninstall failed. The message says what was wrong (which bundle, which requirement, which
 * hash, which index) and what to do; {@link #problem()} classifies it for programs.
 */
public class InstallException extends Exception {

    private static final long serialVersionUID = 1L;

    /** The kinds of failure. */
    public enum Problem {
        /** No repository offers a behaviour that fits the request. */
        NOT_FOUND,
        /** An operator removed this behaviour; automatic requests are refused until an operator allows it. */
        REMOVED_BY_OPERATOR,
        /** A download failed (repository unreachable, I/O error). */
        DOWNLOAD_FAILED,
        /** A download's bytes do not match the SHA-256 or size its index gives. */
        HASH_MISMATCH,
        /** A requirement of the behaviour or of a dependency is met by no bundle in the framework or repositories. */
        UNRESOLVED,
        /** A bundle failed to install or start. */
        START_FAILED,
        /** The behaviour started, but its smart behaviours were not registered with the bus in time. */
        ACTIVATION_TIMEOUT,
        /** The behaviour is not installed by this installer. */
        NOT_INSTALLED,
        /** The installer is stopping. */
        CLOSED,
        /**
         * The journal could not be written (a full disk, a read-only folder): the change was not made, or was undone,
         * so that a restart finds what the installer says.
         */
        JOURNAL_FAILED
    }

    private final Problem problem;

    public InstallException(Problem problem, String message) {
        super(message);
        this.problem = problem;
    }

    public InstallException(Problem problem, String message, Throwable cause) {
        super(message, cause);
        this.problem = problem;
    }

    /** @return what kind of failure this is */
    public Problem problem() {
        return problem;
    }
}
