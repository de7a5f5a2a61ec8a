package eu.brain.iot.containers;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import org.testcontainers.containers.GenericContainer;

/**
 * A fabric node in its container, with the API token it was given, and a plain HTTP/1.1 client for its REST API.
 * The request names the node's own address ({@code Host: 127.0.0.1:8181}), which the REST API accepts, rather than
 * the port Docker maps it to on this machine, which it would refuse (421).
 *
 * <p>Threads: used by the test thread only.
 */
record NodeContainer(String name, String token, GenericContainer<?> container) {
    /** A REST answer: status code and body. */
    record Answer(int status, String body) {
    }

    private static final Duration TIMEOUT = Duration.ofSeconds(10);
    /** Longest answer read: the providers list of the paper's warehouse is a few kB. */
    private static final int MAX_ANSWER = 1 << 20;

    /** GET {@code path} with the token, or without it when {@code withToken} is false. */
    Answer get(String path, boolean withToken) throws IOException {
        try (Socket s = new Socket()) {
            s.connect(new InetSocketAddress(container.getHost(), container.getMappedPort(FabricContainers.HTTP_PORT)),
                    (int) TIMEOUT.toMillis());
            s.setSoTimeout((int) TIMEOUT.toMillis());
            String request = "GET " + path + " HTTP/1.1\r\nHost: 127.0.0.1:" + FabricContainers.HTTP_PORT + "\r\n"
                    + (withToken ? "Authorization: Bearer " + token + "\r\n" : "")
                    + "Accept: application/json\r\nConnection: close\r\n\r\n";
            OutputStream out = s.getOutputStream();
            out.write(request.getBytes(StandardCharsets.US_ASCII));
            out.flush();
            byte[] response = readAll(s.getInputStream());
            String head = new String(response, 0, Math.min(response.length, 8192), StandardCharsets.ISO_8859_1);
            int headerEnd = head.indexOf("\r\n\r\n");
            if (!head.startsWith("HTTP/1.1 ") || headerEnd < 0) {
                throw new IOException("not an HTTP answer from " + name + ": " + head);
            }
            int status = Integer.parseInt(head.substring(9, 12));
            boolean chunked = head.substring(0, headerEnd).toLowerCase(java.util.Locale.ROOT)
                    .contains("transfer-encoding: chunked");
            byte[] body = java.util.Arrays.copyOfRange(response, headerEnd + 4, response.length);
            return new Answer(status, new String(chunked ? unchunk(body) : body, StandardCharsets.UTF_8));
        }
    }

    private static byte[] readAll(InputStream in) throws IOException {
        ByteArrayOutputStream buffer = new ByteArrayOutputStream();
        byte[] chunk = new byte[8192];
        for (int n = in.read(chunk); n >= 0; n = in.read(chunk)) {
            buffer.write(chunk, 0, n);
            if (buffer.size() > MAX_ANSWER) {
                throw new IOException("answer longer than " + MAX_ANSWER + " bytes");
            }
        }
        return buffer.toByteArray();
    }

    /** The body of a chunked answer (RFC 9112 7.1), extensions and trailers ignored. */
    private static byte[] unchunk(byte[] body) throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        int i = 0;
        while (i < body.length) {
            int eol = i;
            while (eol + 1 < body.length && !(body[eol] == '\r' && body[eol + 1] == '\n')) {
                eol++;
            }
            String sizeLine = new String(body, i, eol - i, StandardCharsets.US_ASCII);
            int semicolon = sizeLine.indexOf(';');
            int size;
            try {
                size = Integer.parseInt((semicolon < 0 ? sizeLine : sizeLine.substring(0, semicolon)).trim(), 16);
            } catch (NumberFormatException e) {
                throw new IOException("bad chunk size line '" + sizeLine + "'");
            }
            if (size == 0) {
                break;
            }
            out.write(body, eol + 2, Math.min(size, body.length - eol - 2));
            i = eol + 2 + size + 2;
        }
        return out.toByteArray();
    }

    /** The container's output so far. */
    String logs() {
        return container.getLogs();
    }
}
