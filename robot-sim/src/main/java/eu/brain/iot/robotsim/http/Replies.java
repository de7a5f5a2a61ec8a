package eu.brain.iot.robotsim.http;

import eu.brain.iot.robotsim.world.CommandRejectedException;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionException;

/** Answers an exchange when work done on the world thread completes. */
final class Replies {
    private Replies() {
    }

    /** Answers 200 with the result as JSON, or the error the world gave. */
    static void whenDone(ServerExchange ex, CompletableFuture<?> work) {
        work.whenComplete((result, failure) -> {
            if (failure == null) {
                if (result instanceof byte[] bytes) {
                    ex.json(200, bytes);
                } else {
                    ex.json(200, result);
                }
            } else {
                fail(ex, failure);
            }
        });
    }

    static void fail(ServerExchange ex, Throwable failure) {
        Throwable cause = failure instanceof CompletionException && failure.getCause() != null
                ? failure.getCause() : failure;
        if (cause instanceof ApiException api) {
            ex.error(api);
        } else if (cause instanceof CommandRejectedException rejected) {
            int status = switch (rejected.kind()) {
                case NOT_FOUND -> 404;
                case UNPROCESSABLE -> 422;
                case LIMIT -> 429;
            };
            ex.error(status, rejected.field(), rejected.getMessage(), null);
        } else {
            System.err.println("robot-sim: request " + ex.method() + " " + ex.path() + " failed: " + cause);
            ex.error(500, null, "internal error: " + cause, null);
        }
    }
}
