package eu.brain.iot.bms.impl;

import java.lang.reflect.InvocationTargetException;

import org.osgi.util.promise.Promise;

/** Reading a promise known to be resolved, without the checked exceptions of waiting. */
final class Answers {

    private Answers() {
    }

    /** @return the failure of a resolved promise, or {@code null} when it succeeded */
    static Throwable failure(Promise<?> resolved) {
        try {
            return resolved.getFailure();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return e;
        }
    }

    /** @return the value of a promise resolved successfully */
    static <T> T value(Promise<T> resolved) {
        try {
            return resolved.getValue();
        } catch (InvocationTargetException e) {
            throw new IllegalStateException("value() of a failed promise", e.getCause());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted", e);
        }
    }
}
