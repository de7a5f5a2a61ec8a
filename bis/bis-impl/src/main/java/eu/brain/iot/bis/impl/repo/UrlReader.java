package eu.brain.iot.bis.impl.repo;

import java.io.FileNotFoundException;
import java.io.IOException;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Optional;

/**
 * Reads {@code file:}, {@code http:} and {@code https:} URLs: conditionally (ETag and Last-Modified over HTTP, the
 * modification time of a file) for indexes, plainly for bundles and signatures. Thread-safe (the JDK's HttpClient
 * is); it keeps no state of its own.
 */
public final class UrlReader {

    private final HttpClient http;
    private final Duration timeout;

    public UrlReader(Duration timeout) {
        this.timeout = timeout;
        this.http = HttpClient.newBuilder().connectTimeout(timeout).followRedirects(HttpClient.Redirect.NORMAL)
                .build();
    }

    /** A conditional read: {@link Fetch.Unchanged} when the validators still match. */
    public Fetch fetch(URI uri, Fetch.Validators previous) throws IOException, InterruptedException {
        if ("file".equals(uri.getScheme())) {
            Path path = Path.of(uri);
            long mtime = lastModified(path);
            if (previous.mtime() != 0 && previous.mtime() == mtime) {
                return new Fetch.Unchanged();
            }
            return new Fetch.Content(read(path), null, null, mtime);
        }
        HttpRequest.Builder request = request(uri);
        if (previous.etag() != null) {
            request.header("If-None-Match", previous.etag());
        }
        if (previous.lastModified() != null) {
            request.header("If-Modified-Since", previous.lastModified());
        }
        HttpResponse<byte[]> response = http.send(request.build(), HttpResponse.BodyHandlers.ofByteArray());
        if (response.statusCode() == 304) {
            return new Fetch.Unchanged();
        }
        check(uri, response);
        return new Fetch.Content(response.body(), response.headers().firstValue("ETag").orElse(null),
                response.headers().firstValue("Last-Modified").orElse(null), 0);
    }

    /** @return the bytes at {@code uri} */
    public byte[] read(URI uri) throws IOException, InterruptedException {
        return readIfPresent(uri).orElseThrow(() -> new FileNotFoundException(uri + " does not exist"));
    }

    /** @return the bytes at {@code uri}, or empty when there is no such file (HTTP 404 or 410) */
    public Optional<byte[]> readIfPresent(URI uri) throws IOException, InterruptedException {
        if ("file".equals(uri.getScheme())) {
            Path path = Path.of(uri);
            return Files.exists(path) ? Optional.of(read(path)) : Optional.empty();
        }
        if (!"http".equals(uri.getScheme()) && !"https".equals(uri.getScheme())) {
            throw new IOException(uri + ": only file:, http: and https: URLs are supported");
        }
        HttpResponse<byte[]> response = http.send(request(uri).build(), HttpResponse.BodyHandlers.ofByteArray());
        if (response.statusCode() == 404 || response.statusCode() == 410) {
            return Optional.empty();
        }
        check(uri, response);
        return Optional.of(response.body());
    }

    private HttpRequest.Builder request(URI uri) {
        return HttpRequest.newBuilder(uri).timeout(timeout).GET();
    }

    private static void check(URI uri, HttpResponse<byte[]> response) throws IOException {
        if (response.statusCode() != 200) {
            throw new IOException(uri + " answered HTTP " + response.statusCode());
        }
    }

    private static long lastModified(Path path) throws IOException {
        try {
            return Files.getLastModifiedTime(path).toMillis();
        } catch (NoSuchFileException e) {
            throw new FileNotFoundException(path + " does not exist");
        }
    }

    private static byte[] read(Path path) throws IOException {
        try {
            return Files.readAllBytes(path);
        } catch (NoSuchFileException e) {
            throw new FileNotFoundException(path + " does not exist");
        }
    }
}
