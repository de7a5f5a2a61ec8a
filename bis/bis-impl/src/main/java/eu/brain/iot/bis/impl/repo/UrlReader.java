package eu.brain.iot.bis.impl.repo;

import java.io.ByteArrayOutputStream;
import java.io.FileNotFoundException;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.time.Duration;
import java.util.HexFormat;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicReference;

/**
 * Reads {@code file:}, {@code http:} and {@code https:} URLs, every read bounded in size and in time: indexes and
 * signatures into memory up to a given size, bundles streamed into a file (with their SHA-256 computed on the way) up
 * to a given size; over HTTP, {@code timeout} bounds the wait for a connection and the headers, {@code deadline} the
 * whole read, body included. Every error names the URL. Conditional reads (ETag and Last-Modified over HTTP, the
 * modification time of a file) for indexes.
 * <p>
 * Thread-safe (the JDK's HttpClient is; each read keeps its state on its own stack and in its own body subscriber);
 * a read blocks its calling thread for at most the deadline.
 */
public final class UrlReader {

    private static final int OK = 200;
    private static final int NOT_MODIFIED = 304;
    private static final int NOT_FOUND = 404;
    private static final int GONE = 410;

    private final HttpClient http;
    private final Duration timeout;
    private final Duration deadline;

    public UrlReader(Duration timeout, Duration deadline) {
        this.timeout = timeout;
        this.deadline = deadline;
        this.http = HttpClient.newBuilder().connectTimeout(timeout).followRedirects(HttpClient.Redirect.NORMAL)
                .build();
    }

    /** A body longer than allowed: refused, and nothing of it kept. */
    public static final class TooLong extends IOException {
        private static final long serialVersionUID = 1L;

        TooLong(String message) {
            super(message);
        }
    }

    /** A bundle read into a file: where, how long, its SHA-256 (lower-case hex). */
    public record Downloaded(Path file, long size, String sha256) {
    }

    /** A conditional read of at most {@code maxBytes}: {@link Fetch.Unchanged} when the validators still match. */
    public Fetch fetch(URI uri, Fetch.Validators previous, long maxBytes) throws IOException, InterruptedException {
        if ("file".equals(uri.getScheme())) {
            Path path = Path.of(uri);
            long mtime = lastModified(path);
            if (previous.mtime() != 0 && previous.mtime() == mtime) {
                return new Fetch.Unchanged();
            }
            return new Fetch.Content(read(path, maxBytes), null, null, mtime);
        }
        HttpRequest.Builder request = request(uri);
        if (previous.etag() != null) {
            request.header("If-None-Match", previous.etag());
        }
        if (previous.lastModified() != null) {
            request.header("If-Modified-Since", previous.lastModified());
        }
        HttpResponse<byte[]> response = send(uri, request.build(), maxBytes, null, Memory::new);
        if (response.statusCode() == NOT_MODIFIED) {
            return new Fetch.Unchanged();
        }
        check(uri, response.statusCode());
        return new Fetch.Content(response.body(), response.headers().firstValue("ETag").orElse(null),
                response.headers().firstValue("Last-Modified").orElse(null), 0);
    }

    /** @return the bytes at {@code uri} (at most {@code maxBytes}), or empty when there is none (HTTP 404 or 410) */
    public Optional<byte[]> readIfPresent(URI uri, long maxBytes) throws IOException, InterruptedException {
        if ("file".equals(uri.getScheme())) {
            Path path = Path.of(uri);
            return Files.exists(path) ? Optional.of(read(path, maxBytes)) : Optional.empty();
        }
        supported(uri);
        HttpResponse<byte[]> response = send(uri, request(uri).build(), maxBytes, null, Memory::new);
        if (response.statusCode() == NOT_FOUND || response.statusCode() == GONE) {
            return Optional.empty();
        }
        check(uri, response.statusCode());
        return Optional.of(response.body());
    }

    /**
     * Streams the bytes at {@code uri} into {@code target} (created or replaced), at most {@code maxBytes}, computing
     * their SHA-256. On any failure the partial file is deleted.
     *
     * @param transfer told how far the read got, for people asking
     */
    public Downloaded download(URI uri, Path target, long maxBytes, Transfer transfer) throws IOException,
            InterruptedException {
        if ("file".equals(uri.getScheme())) {
            Path path = Path.of(uri);
            long size = size(path);
            if (size > maxBytes) {
                throw new TooLong(uri + " is " + size + " bytes, more than the " + maxBytes + " allowed; refused");
            }
            try (InputStream in = Files.newInputStream(path); OutputStream out = Files.newOutputStream(target)) {
                MessageDigest digest = sha256();
                byte[] buffer = new byte[64 * 1024];
                long total = 0;
                for (int n; (n = in.read(buffer)) >= 0;) {
                    total += n;
                    if (total > maxBytes) {
                        throw new TooLong(uri + " grew beyond the " + maxBytes + " bytes allowed; refused");
                    }
                    digest.update(buffer, 0, n);
                    out.write(buffer, 0, n);
                }
                return new Downloaded(target, total, HexFormat.of().formatHex(digest.digest()));
            } catch (IOException e) {
                Files.deleteIfExists(target);
                throw e;
            }
        }
        supported(uri);
        HttpResponse<Downloaded> response = send(uri, request(uri).build(), maxBytes, transfer,
                () -> new ToFile(target));
        try {
            check(uri, response.statusCode());
        } catch (IOException e) {
            Files.deleteIfExists(target);
            throw e;
        }
        return response.body();
    }

    /**
     * One HTTP exchange, bounded: the body goes to a fresh sink only for a 200 answer (any other is cut off at once),
     * and the whole exchange is abandoned at the deadline.
     */
    private <T> HttpResponse<T> send(URI uri, HttpRequest request, long maxBytes, Transfer transfer,
            java.util.function.Supplier<BoundedBody.Sink<T>> sinks) throws IOException, InterruptedException {
        AtomicReference<BoundedBody<T>> body = new AtomicReference<>();
        HttpResponse.BodyHandler<T> handler = info -> {
            if (info.statusCode() != OK) {
                return new CutOff<T>(); // the status says it all: no body is read
            }
            BoundedBody<T> b = new BoundedBody<>(uri, maxBytes, sinks.get());
            body.set(b);
            if (transfer != null) {
                transfer.receivedBy(b::received);
            }
            return b;
        };
        CompletableFuture<HttpResponse<T>> answer = http.sendAsync(request, handler);
        try {
            return answer.get(deadline.toMillis(), TimeUnit.MILLISECONDS);
        } catch (TimeoutException e) {
            BoundedBody<T> b = body.get();
            IOException late = new IOException(uri + " did not " + (b == null ? "answer" : "send its whole body")
                    + " within " + deadline.toMillis() + " ms (download.deadline.ms)"
                    + (b == null ? "" : "; " + b.received() + " bytes had arrived") + "; abandoned");
            if (b != null) {
                b.abort(late);
            }
            answer.cancel(true);
            throw late;
        } catch (InterruptedException e) {
            BoundedBody<T> b = body.get();
            if (b != null) {
                b.abort(new IOException(uri + ": read interrupted"));
            }
            answer.cancel(true);
            throw e;
        } catch (ExecutionException e) {
            Throwable cause = e.getCause();
            if (cause instanceof TooLong tooLong) {
                throw new TooLong(tooLong.getMessage());
            }
            String message = Errors.describe(cause);
            throw new IOException(message.contains(uri.toString()) ? message : uri + ": " + message, cause);
        }
    }

    private HttpRequest.Builder request(URI uri) {
        return HttpRequest.newBuilder(uri).timeout(timeout).GET();
    }

    private static void supported(URI uri) throws IOException {
        if (!"http".equals(uri.getScheme()) && !"https".equals(uri.getScheme())) {
            throw new IOException(uri + ": only file:, http: and https: URLs are supported");
        }
    }

    private static void check(URI uri, int status) throws IOException {
        if (status != OK) {
            throw new IOException(uri + " answered HTTP " + status);
        }
    }

    private static long lastModified(Path path) throws IOException {
        try {
            return Files.getLastModifiedTime(path).toMillis();
        } catch (NoSuchFileException e) {
            throw new FileNotFoundException(path + " does not exist");
        }
    }

    private static long size(Path path) throws IOException {
        try {
            return Files.size(path);
        } catch (NoSuchFileException e) {
            throw new FileNotFoundException(path + " does not exist");
        }
    }

    private static byte[] read(Path path, long maxBytes) throws IOException {
        long size = size(path);
        if (size > maxBytes) {
            throw new TooLong(path + " is " + size + " bytes, more than the " + maxBytes + " allowed; refused");
        }
        try (InputStream in = Files.newInputStream(path)) {
            byte[] bytes = in.readNBytes((int) Math.min(Integer.MAX_VALUE - 8, maxBytes + 1));
            if (bytes.length > maxBytes) {
                throw new TooLong(path + " grew beyond the " + maxBytes + " bytes allowed; refused");
            }
            return bytes;
        }
    }

    static MessageDigest sha256() {
        try {
            return MessageDigest.getInstance("SHA-256");
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException(e);
        }
    }

    /** Reads no body: cancels it at once (an error page may be endless too) and completes with null. */
    private static final class CutOff<T> implements HttpResponse.BodySubscriber<T> {
        private final CompletableFuture<T> result = new CompletableFuture<>();

        @Override
        public java.util.concurrent.CompletionStage<T> getBody() {
            return result;
        }

        @Override
        public void onSubscribe(java.util.concurrent.Flow.Subscription subscription) {
            subscription.cancel();
            result.complete(null);
        }

        @Override
        public void onNext(java.util.List<ByteBuffer> item) {
            // cancelled: nothing is read
        }

        @Override
        public void onError(Throwable throwable) {
            result.complete(null);
        }

        @Override
        public void onComplete() {
            result.complete(null);
        }
    }

    /** A body in memory; {@link BoundedBody} keeps it within its limit. */
    private static final class Memory implements BoundedBody.Sink<byte[]> {
        private final ByteArrayOutputStream bytes = new ByteArrayOutputStream();

        @Override
        public void write(ByteBuffer buffer) {
            byte[] chunk = new byte[buffer.remaining()];
            buffer.get(chunk);
            bytes.write(chunk, 0, chunk.length);
        }

        @Override
        public byte[] finish() {
            return bytes.toByteArray();
        }

        @Override
        public void discard() {
            bytes.reset();
        }
    }

    /** A body streamed into a file, hashed on the way; the partial file is deleted when the read fails. */
    private static final class ToFile implements BoundedBody.Sink<Downloaded> {
        private final Path target;
        private final MessageDigest digest = sha256();
        private FileChannel channel;
        private long size;

        ToFile(Path target) {
            this.target = target;
        }

        @Override
        public synchronized void write(ByteBuffer buffer) throws IOException {
            if (channel == null) {
                channel = FileChannel.open(target, StandardOpenOption.CREATE, StandardOpenOption.WRITE,
                        StandardOpenOption.TRUNCATE_EXISTING);
            }
            ByteBuffer forDigest = buffer.duplicate();
            digest.update(forDigest);
            size += buffer.remaining();
            while (buffer.hasRemaining()) {
                channel.write(buffer);
            }
        }

        @Override
        public synchronized Downloaded finish() throws IOException {
            if (channel == null) {
                Files.write(target, new byte[0]);
            } else {
                channel.close();
            }
            return new Downloaded(target, size, HexFormat.of().formatHex(digest.digest()));
        }

        @Override
        public synchronized void discard() {
            try {
                if (channel != null) {
                    channel.close();
                }
                Files.deleteIfExists(target);
            } catch (IOException e) {
                // a partial file that cannot be deleted stays in the framework's data area, wiped at the next start
            }
        }
    }
}
