package eu.brain.iot.robotsim.http;

import io.netty.handler.codec.http.HttpHeaderNames;
import io.netty.handler.codec.http.HttpHeaders;
import io.netty.handler.codec.http.HttpMethod;
import io.netty.handler.codec.http.HttpVersion;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.TreeSet;

/**
 * What keeps web pages away from the simulator, checked before a request is routed: a browser on the same machine
 * can send requests to 127.0.0.1 from any page, and a page whose name resolves to 127.0.0.1 (DNS rebinding) even reads
 * the answers. So: the {@code Host} header must name this server (a configured name and its port; 421 otherwise), an
 * {@code Origin} header, when present, must be this server's own origin (403), and a request that may change state
 * (any method but GET, HEAD, OPTIONS and TRACE) must say {@code Content-Type: application/json} (415), which a page
 * can only send after a CORS preflight that robot-sim never grants. Immutable; shared by all I/O threads.
 */
final class RequestGate {
    private static final Set<HttpMethod> SAFE = Set.of(HttpMethod.GET, HttpMethod.HEAD, HttpMethod.OPTIONS,
            HttpMethod.TRACE);

    private final Set<String> hostNames;

    /** @param hostNames accepted names, lower case, IPv6 addresses in brackets */
    RequestGate(Set<String> hostNames) {
        this.hostNames = Set.copyOf(hostNames);
    }

    /**
     * @param port the port this request came in on
     * @throws ApiException the refusal (field: the header at fault)
     */
    void check(HttpMethod method, HttpVersion version, HttpHeaders headers, int port) throws ApiException {
        checkHost(version, headers, port);
        checkOrigin(headers, port);
        if (!SAFE.contains(method)) {
            checkContentType(method, headers);
        }
    }

    private void checkHost(HttpVersion version, HttpHeaders headers, int port) throws ApiException {
        List<String> hosts = headers.getAll(HttpHeaderNames.HOST);
        if (hosts.isEmpty()) {
            if (version.equals(HttpVersion.HTTP_1_0)) {
                return; // HTTP/1.0 has no Host; browsers never speak it
            }
            throw new ApiException(400, "Host", "missing Host header (HTTP/1.1 requires one, e.g. Host: 127.0.0.1:"
                    + port + ")");
        }
        if (hosts.size() > 1) {
            throw new ApiException(400, "Host", "more than one Host header");
        }
        if (!isOwn(hosts.get(0), port)) {
            throw new ApiException(421, "Host", "Host '" + hosts.get(0) + "' is not a name of this server (accepted: "
                    + names(port) + "; robot-sim's --allow-host NAME adds one)");
        }
    }

    private void checkOrigin(HttpHeaders headers, int port) throws ApiException {
        List<String> origins = headers.getAll(HttpHeaderNames.ORIGIN);
        if (origins.isEmpty()) {
            return; // not sent by a browser's cross-origin request: curl, the edge, tests
        }
        String origin = origins.get(0);
        String prefix = "http://";
        boolean own = origins.size() == 1 && origin.regionMatches(true, 0, prefix, 0, prefix.length())
                && isOwn(origin.substring(prefix.length()), port);
        if (!own) {
            throw new ApiException(403, "Origin", "cross-origin request refused: Origin '" + origin
                    + "' is not this server (accepted: no Origin, or http:// and one of " + names(port) + ")");
        }
    }

    private static void checkContentType(HttpMethod method, HttpHeaders headers) throws ApiException {
        String type = headers.get(HttpHeaderNames.CONTENT_TYPE);
        String media = type == null ? "" : type.split(";", 2)[0].strip().toLowerCase(Locale.ROOT);
        if (!media.equals("application/json")) {
            throw new ApiException(415, "Content-Type", method + " needs Content-Type: application/json, "
                    + (type == null ? "found none" : "found '" + type + "'")
                    + " (with curl: -H 'Content-Type: application/json')");
        }
    }

    /** {@code authority} is {@code name[:port]}; the port must be this server's (none means 80). */
    private boolean isOwn(String authority, int port) {
        String a = authority.strip().toLowerCase(Locale.ROOT);
        int close = a.lastIndexOf(']');
        int colon = a.lastIndexOf(':');
        String name = a;
        int given = 80;
        if (colon > close) {
            name = a.substring(0, colon);
            try {
                given = Integer.parseInt(a.substring(colon + 1));
            } catch (NumberFormatException e) {
                return false;
            }
        }
        return given == port && hostNames.contains(name);
    }

    private String names(int port) {
        StringBuilder out = new StringBuilder();
        for (String n : new TreeSet<>(hostNames)) {
            out.append(out.length() == 0 ? "" : ", ").append(n).append(':').append(port);
        }
        return out.toString();
    }
}
