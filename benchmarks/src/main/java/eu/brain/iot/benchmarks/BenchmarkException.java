package eu.brain.iot.benchmarks;

/** A benchmark that cannot go on, with a message that says why and what to do. */
final class BenchmarkException extends RuntimeException {

    private static final long serialVersionUID = 1L;

    BenchmarkException(String message) {
        super(message);
    }
}
