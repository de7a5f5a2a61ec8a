package eu.brain.iot.edge.rest.integration;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

/**
 * HTTP written by hand on a socket, for what Java's HTTP client will not send (a foreign {@code Host}, malformed
 * requests, slow bodies): one request with {@code Connection: close}, read to the end.
 */
final class RawHttp {

    static final ObjectMapper JSON = new ObjectMapper();

    /** An answer: status, headers (lower-case names), body. */
    record Answer(int status, Map<String, String> headers, String body) {
        JsonNode json() throws IOException {
            return JSON.readTree(body);
        }

        String header(String name) {
            return headers.get(name.toLowerCase(Locale.ROOT));
        }
    }

    private RawHttp() {
    }

    /** Opens a connection to the server of {@code base} (from {@code local}, when not null). */
    static Socket connect(URI base, InetAddress local) throws IOException {
        Socket s = new Socket();
        if (local != null) {
            s.bind(new InetSocketAddress(local, 0));
        }
        s.connect(new InetSocketAddress(base.getHost(), base.getPort()), 5_000);
        s.setSoTimeout(15_000);
        return s;
    }

    /** Sends {@code head} (request line and headers, without the closing blank line) and {@code body}. */
    static Answer exchange(URI base, String head, String body) throws IOException {
        try (Socket s = connect(base, null)) {
            String request = head + "\r\nConnection: close\r\n\r\n" + (body == null ? "" : body);
            s.getOutputStream().write(request.getBytes(StandardCharsets.UTF_8));
            s.getOutputStream().flush();
            return read(s.getInputStream());
        } catch (IOException e) {
            throw new IOException(e.getMessage() + " (request: " + head.substring(0, Math.min(head.length(), 200))
                    + ")", e);
        }
    }

    /** A GET of {@code target} with {@code Host} naming the server as the client would (127.0.0.1:port). */
    static String host(URI base) {
        return "Host: " + base.getHost() + ":" + base.getPort();
    }

    /** Reads one answer: its head, then as many bytes as its Content-Length says, or to the end of the connection. */
    static Answer read(InputStream in) throws IOException {
        ByteArrayOutputStream all = new ByteArrayOutputStream();
        int end = -1;
        long length = -1;
        for (int b; (b = in.read()) >= 0;) {
            all.write(b);
            if (end < 0 && all.size() >= 4 && all.toString(StandardCharsets.ISO_8859_1).endsWith("\r\n\r\n")) {
                end = all.size() - 4;
                java.util.regex.Matcher m = java.util.regex.Pattern.compile("(?im)^content-length:\\s*(\\d+)")
                        .matcher(all.toString(StandardCharsets.ISO_8859_1));
                length = m.find() ? Long.parseLong(m.group(1)) : -1;
            }
            if (end >= 0 && length < 0 && all.toString(StandardCharsets.ISO_8859_1).endsWith("\r\n0\r\n\r\n")) {
                break; // the last chunk
            }
            if (end >= 0 && length >= 0 && all.size() - end - 4 >= length) {
                break;
            }
        }
        String text = all.toString(StandardCharsets.UTF_8);
        if (end < 0) {
            throw new IOException("no complete HTTP answer: '" + text + "'");
        }
        String[] lines = text.substring(0, end).split("\r\n");
        int status = Integer.parseInt(lines[0].split(" ")[1]);
        Map<String, String> headers = new TreeMap<>();
        for (int i = 1; i < lines.length; i++) {
            int colon = lines[i].indexOf(':');
            headers.put(lines[i].substring(0, colon).strip().toLowerCase(Locale.ROOT), lines[i].substring(colon + 1).strip());
        }
        return new Answer(status, headers, text.substring(end + 4));
    }
}
