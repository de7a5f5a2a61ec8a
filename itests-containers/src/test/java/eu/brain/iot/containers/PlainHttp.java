package eu.brain.iot.containers;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.time.Duration;

/**
 * A plain HTTP/1.1 client for the containers' REST APIs: one GET per connection, the answer bounded in size and time.
 *
 * <p>Stateless.
 */
final class PlainHttp {
    /** An answer: status code and body. */
    record Answer(int status, String body) {
    }

    private static final Duration TIMEOUT = Duration.ofSeconds(10);
    /** Longest answer read: the providers list and robot-sim's world of the paper's warehouse are a few kB. */
    private static final int MAX_ANSWER = 1 << 20;

    private PlainHttp() {
    }

    /**
     * GET {@code path} from {@code host:port}.
     *
     * @param hostHeader the {@code Host} the request names
     * @param token      the bearer token, or null for none
     */
    static Answer get(String host, int port, String hostHeader, String path, String token) throws IOException {
        try (Socket s = new Socket()) {
            s.connect(new InetSocketAddress(host, port), (int) TIMEOUT.toMillis());
            s.setSoTimeout((int) TIMEOUT.toMillis());
            String request = "GET " + path + " HTTP/1.1\r\nHost: " + hostHeader + "\r\n"
                    + (token != null ? "Authorization: Bearer " + token + "\r\n" : "")
                    + "Accept: application/json\r\nConnection: close\r\n\r\n";
            OutputStream out = s.getOutputStream();
            out.write(request.getBytes(StandardCharsets.US_ASCII));
            out.flush();
            byte[] response = readAll(s.getInputStream());
            String head = new String(response, 0, Math.min(response.length, 8192), StandardCharsets.ISO_8859_1);
            int headerEnd = head.indexOf("\r\n\r\n");
            if (!head.startsWith("HTTP/1.1 ") || headerEnd < 0) {
                throw new IOException("not an HTTP answer from " + host + ":" + port + ": " + head);
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

}
