package eu.brain.iot.edge.rest;

import java.io.IOException;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionException;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicReference;

import org.osgi.service.log.Logger;

import eu.brain.iot.edge.api.CommandOutcome;
import eu.brain.iot.edge.model.api.DeviceModel;
import eu.brain.iot.edge.model.api.UnknownResourceException;
import jakarta.servlet.AsyncContext;
import jakarta.servlet.AsyncEvent;
import jakarta.servlet.AsyncListener;
import jakarta.servlet.http.HttpServletRequest;
import jakarta.servlet.http.HttpServletResponse;

/**
 * The ACT side of {@code /sensinact}: {@code POST .../resources/{action}/act} runs the action through
 * {@link DeviceModel#act} and answers with the device's outcome. The request is asynchronous: no container thread
 * waits for the robot, and the wait is bounded ({@code act.timeout.ms}, then 504).
 * <p>
 * Status codes: 200 accepted; 409 the device refused (its reason in {@code error}); 502 the device could not be
 * reached; 504 no answer in time (the command may still be carried out); 404 unknown provider or action; 400 bad
 * parameters or malformed JSON; 408 body too slow; 413 body too large.
 */
final class Acts {

    static final String EXAMPLE = "{\"x\":9,\"y\":7} (goTo) or {} (open, close, pick, place)";

    private final DeviceModel model;
    private final long timeoutMillis;
    private final int maxBodyBytes;
    private final long bodyTimeoutMillis;
    private final ScheduledExecutorService timer;
    private final Logger log;
    /** Slow bodies refused: one short line per client address a minute, however many it sends. */
    private final RefusalLog refusals;

    /**
     * @param timer runs the body deadlines and nothing that waits (owned by the caller, which shuts it down)
     */
    Acts(DeviceModel model, long timeoutMillis, int maxBodyBytes, long bodyTimeoutMillis,
            ScheduledExecutorService timer, Logger log) {
        this.model = model;
        this.timeoutMillis = timeoutMillis;
        this.maxBodyBytes = maxBodyBytes;
        this.bodyTimeoutMillis = bodyTimeoutMillis;
        this.timer = timer;
        this.log = log;
        this.refusals = new RefusalLog(log, 60_000, System::nanoTime);
    }

    /**
     * Answers 413 at once for a declared length over {@code act.max.body.bytes}; otherwise reads the body without
     * holding a thread ({@link BodyReader}), within {@code act.body.timeout.ms} (then 408, and the connection
     * closes), and runs the action.
     */
    void act(Route r, HttpServletRequest req, HttpServletResponse resp) throws IOException {
        if (req.getContentLengthLong() > maxBodyBytes) {
            throw BodyReader.tooLarge(maxBodyBytes); // before reading a byte of it
        }
        AsyncContext async = req.startAsync();
        AtomicBoolean answered = new AtomicBoolean();
        // A backstop only: the body's deadline and the bounded wait below answer first.
        async.setTimeout(bodyTimeoutMillis + timeoutMillis + 5_000);
        async.addListener(new AsyncListener() {
            @Override
            public void onTimeout(AsyncEvent event) {
                answer(async, answered, 504, Replies.error(504, "no answer in time"));
            }

            @Override
            public void onComplete(AsyncEvent event) {
            }

            @Override
            public void onError(AsyncEvent event) {
                answered.set(true); // the client is gone: nothing to answer
            }

            @Override
            public void onStartAsync(AsyncEvent event) {
            }
        });
        AtomicReference<ScheduledFuture<?>> deadline = new AtomicReference<>();
        String client = req.getRemoteAddr();
        BodyReader reader = new BodyReader(req.getInputStream(), maxBodyBytes, body -> {
            cancel(deadline);
            try {
                run(r, body, async, answered);
            } catch (HttpError e) {
                answer(async, answered, e);
            } catch (RuntimeException e) {
                // A bug of ours: the log gets the stack trace, the caller a short message.
                log.error("internal error on ACT " + r.path(), e);
                answer(async, answered, new HttpError(500, "internal error of the edge (" + e.getClass().getSimpleName()
                        + "); the node's log (Gogo: log error) has the details"));
            }
        }, e -> {
            cancel(deadline);
            answer(async, answered, e);
        });
        deadline.set(timer.schedule(() -> {
            if (reader.abandon()) {
                HttpError e = HttpError.closing(408, "body", "the body did not arrive within " + bodyTimeoutMillis
                        + " ms (act.body.timeout.ms); send the whole request at once");
                refusals.refused(client, "408, an ACT's body did not arrive within " + bodyTimeoutMillis
                        + " ms (act.body.timeout.ms)");
                startQuietly(async, () -> answer(async, answered, e));
            }
        }, bodyTimeoutMillis, TimeUnit.MILLISECONDS));
        reader.start();
    }

    private static void cancel(AtomicReference<ScheduledFuture<?>> deadline) {
        ScheduledFuture<?> f = deadline.get();
        if (f != null) {
            f.cancel(false);
        }
    }

    /** The body is all there: parse it, run the action, answer when the device does (on a container thread). */
    private void run(Route r, byte[] body, AsyncContext async, AtomicBoolean answered) {
        Map<String, Object> params = ActBody.parameters(body, EXAMPLE);
        CompletionStage<CommandOutcome> stage;
        try {
            stage = model.act(r.provider(), r.service(), r.resource(), params);
        } catch (UnknownResourceException e) {
            throw HttpError.notFound(Echo.cut(e.getMessage(), Echo.MAX_MESSAGE_CHARS));
        } catch (IllegalArgumentException e) {
            throw HttpError.about(400, "body", e.getMessage() + "; body received: " + received(params));
        }
        // A copy, so that the timeout never completes the edge's own future.
        CompletableFuture<CommandOutcome> bounded = stage.toCompletableFuture().thenApply(o -> o)
                .orTimeout(timeoutMillis, TimeUnit.MILLISECONDS);
        // Answer on a container thread (async.start), never on the edge's or the HTTP client's thread.
        bounded.whenComplete((outcome, error) -> startQuietly(async, () -> {
            Map<String, Object> answer;
            int status;
            if (error != null) {
                Throwable cause = error instanceof CompletionException && error.getCause() != null ? error.getCause()
                        : error;
                status = cause instanceof TimeoutException ? 504 : 502;
                answer = Replies.error(status, status == 504
                        ? r.provider() + " did not answer " + r.resource() + " within " + timeoutMillis
                                + " ms (act.timeout.ms); it may still carry it out: follow GET /sensinact/providers/"
                                + r.provider()
                        : "the edge could not run " + r.resource() + " on " + r.provider() + ": " + cause);
            } else {
                status = outcome.accepted ? 200 : outcome.status == 0 ? 502 : 409;
                answer = Views.outcome(r.provider(), r.service(), r.resource(), outcome);
                if (!outcome.accepted) {
                    answer.put("error", status == 502 ? r.provider() + " could not be reached: " + outcome.reason
                            : r.provider() + " refused " + r.resource() + ": " + outcome.reason);
                }
                answer.put("status", status);
            }
            answer(async, answered, status, answer);
        }));
    }

    private static String received(Map<String, Object> params) {
        try {
            return Replies.MAPPER.writeValueAsString(params);
        } catch (IOException e) {
            return String.valueOf(params);
        }
    }

    /** The container refuses a new task once the request is over (client gone, backstop timeout): nothing to do. */
    private static void startQuietly(AsyncContext async, Runnable task) {
        try {
            async.start(task);
        } catch (IllegalStateException e) {
            // the request already ended
        }
    }

    private void answer(AsyncContext async, AtomicBoolean answered, HttpError e) {
        if (e.close) {
            ((HttpServletResponse) async.getResponse()).setHeader("Connection", "close");
        }
        answer(async, answered, e.status, Replies.error(e.status, e.field, e.getMessage()));
    }

    private void answer(AsyncContext async, AtomicBoolean answered, int status, Map<String, Object> body) {
        if (!answered.compareAndSet(false, true)) {
            return;
        }
        try {
            Replies.json((HttpServletResponse) async.getResponse(), status, body);
        } catch (IOException | RuntimeException e) {
            log.debug("could not answer an ACT (the client may have gone): " + e);
        } finally {
            try {
                async.complete();
            } catch (IllegalStateException e) {
                // already completed by the container (client gone, timeout)
            }
        }
    }
}
