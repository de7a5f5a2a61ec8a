package eu.brain.iot.bip.smc.engine;

import eu.brain.iot.bip.smc.runtime.ExternSimulationException;
import eu.brain.iot.bip.smc.runtime.StochasticException;

/** Words a failure of a sampling thread for the user: which trace, what went wrong, what to do. */
final class TraceFailures {

    private TraceFailures() {
    }

    /**
     * @param trace the failing trace's index, or -1 when the failure is not a trace's (creating the system)
     * @param step what the system was executing or had just executed ({@code SimulatedSystem.lastStep()})
     */
    static String describe(long trace, long seed, String step, Throwable e) {
        String where = trace < 0 ? "the simulated system could not be created"
                : "trace " + trace + " (seed " + seed + ") failed " + (step.isEmpty() ? "in its initial state"
                        : "at step " + step);
        return where + ": " + what(e) + (trace < 0 ? "" : " (the same seed gives the same trace again)");
    }

    private static String what(Throwable e) {
        if (e instanceof StochasticException || e instanceof ExternSimulationException) {
            return e.getMessage();
        } else if (e instanceof LinkageError) {
            return "the Java compiled for the model failed to link (" + e + "): a bug of bip's compiled engine, "
                    + "please report it with the model; '--engine interpreted' checks the same query without it";
        } else if (e instanceof StackOverflowError) {
            return "the model's code overflowed the stack (" + e + ")";
        } else if (e instanceof RuntimeException) {
            StackTraceElement[] frames = e.getStackTrace();
            return "the model's code threw " + e + (frames.length == 0 ? "" : " at " + frames[0])
                    + "; correct the model (a division by zero, a value out of range, ...)";
        }
        return "the sampling thread failed with " + e;
    }
}
