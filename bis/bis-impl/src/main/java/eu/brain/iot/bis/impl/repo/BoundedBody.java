package eu.brain.iot.bis.impl.repo;

import java.io.IOException;
import java.net.URI;
import java.net.http.HttpResponse;
import java.nio.ByteBuffer;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.Flow;

/**
 * The body of one HTTP answer, handed to a {@link Sink} as it arrives and never beyond {@code maxBytes}: a longer
 * body is cancelled (the connection closed) and fails with an error naming the URL. {@link #abort} ends it from
 * outside (the read's deadline). {@link #received()} tells how far it got.
 * <p>
 * Threads: the HTTP client calls {@code onSubscribe}/{@code onNext}/{@code onError}/{@code onComplete} one at a time
 * on its own threads; {@link #abort} comes from the deadline's thread. The subscription and the received count are
 * volatile; the result completes once (a {@link CompletableFuture}).
 */
final class BoundedBody<T> implements HttpResponse.BodySubscriber<T> {

    /** Where the bytes go: a bounded memory buffer (indexes) or a file (bundles). */
    interface Sink<T> {
        void write(ByteBuffer buffer) throws IOException;

        /** @return what the read made, once the body is complete */
        T finish() throws IOException;

        /** Releases what the sink holds after a failure (closes and deletes a partial file). */
        void discard();
    }

    private final URI uri;
    private final long maxBytes;
    private final Sink<T> sink;
    private final CompletableFuture<T> result = new CompletableFuture<>();
    private volatile Flow.Subscription subscription;
    private volatile long received;

    BoundedBody(URI uri, long maxBytes, Sink<T> sink) {
        this.uri = uri;
        this.maxBytes = maxBytes;
        this.sink = sink;
    }

    long received() {
        return received;
    }

    /** Ends the read with this error, unless it is complete already. */
    void abort(IOException why) {
        if (result.completeExceptionally(why)) {
            Flow.Subscription s = subscription;
            if (s != null) {
                s.cancel();
            }
            sink.discard();
        }
    }

    @Override
    public CompletionStage<T> getBody() {
        return result;
    }

    @Override
    public void onSubscribe(Flow.Subscription s) {
        subscription = s;
        if (result.isDone()) {
            s.cancel();
        } else {
            s.request(1);
        }
    }

    @Override
    public void onNext(List<ByteBuffer> buffers) {
        if (result.isDone()) {
            return;
        }
        try {
            for (ByteBuffer buffer : buffers) {
                long total = received + buffer.remaining();
                if (total > maxBytes) {
                    abort(new UrlReader.TooLong(uri + " is longer than the " + maxBytes + " bytes allowed (more than "
                            + maxBytes + " bytes sent); refused"));
                    return;
                }
                sink.write(buffer);
                received = total;
            }
            subscription.request(1);
        } catch (IOException e) {
            abort(new IOException("cannot store what " + uri + " sends: " + Errors.describe(e), e));
        }
    }

    @Override
    public void onError(Throwable throwable) {
        abort(new IOException(uri + ": the transfer failed after " + received + " bytes: "
                + Errors.describe(throwable), throwable));
    }

    @Override
    public void onComplete() {
        try {
            result.complete(sink.finish());
        } catch (IOException e) {
            abort(new IOException("cannot store what " + uri + " sent: " + Errors.describe(e), e));
        }
    }
}
