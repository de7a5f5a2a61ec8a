package eu.brain.iot.edge.rest;

import java.util.Locale;
import java.util.Set;
import java.util.TreeSet;

/**
 * The names this server answers to, for the {@code Host} and {@code Origin} checks that stop web pages from
 * reaching the API through DNS rebinding or cross-site requests: the loopback names, the bound address, and the
 * configured {@code allowed.hosts}, each with the port the request came in on. Names are compared without case; a
 * {@code Host} without a port means port 80.
 * <p>
 * Threads: immutable after construction, read by any number of container threads.
 */
final class HostNames {

    private static final Set<String> LOOPBACK = Set.of("127.0.0.1", "localhost", "[::1]");

    private final Set<String> names = new TreeSet<>();

    /**
     * @param bindHost the address Felix HTTP binds ({@code null} or a wildcard: every interface, not a name)
     * @param allowed  more names, with or without a port
     */
    HostNames(String bindHost, String[] allowed) {
        names.addAll(LOOPBACK);
        if (bindHost != null && !bindHost.isBlank() && !bindHost.equals("0.0.0.0") && !bindHost.equals("::")
                && !bindHost.equals("[::]")) {
            names.add(bracketed(bindHost.strip().toLowerCase(Locale.ROOT)));
        }
        for (String a : allowed) {
            if (!a.isBlank()) {
                names.add(a.strip().toLowerCase(Locale.ROOT));
            }
        }
    }

    private static String bracketed(String host) {
        return host.contains(":") && !host.startsWith("[") ? "[" + host + "]" : host;
    }

    /** Whether {@code host} (a Host header's value: name or name:port) names this server on {@code port}. */
    boolean accepts(String host, int port) {
        if (host == null) {
            return false;
        }
        String h = host.strip().toLowerCase(Locale.ROOT);
        boolean hasPort = h.lastIndexOf(':') > h.lastIndexOf(']');
        String withPort = hasPort ? h : h + ":80";
        return names.contains(withPort) || names.stream().anyMatch(n -> withPort.equals(n + ":" + port));
    }

    /** Whether {@code origin} (an Origin header's value) is this server's own: http:// and an accepted name. */
    boolean acceptsOrigin(String origin, int port) {
        String o = origin.strip().toLowerCase(Locale.ROOT);
        return o.startsWith("http://") && !o.substring(7).contains("/") && accepts(o.substring(7), port);
    }

    /** The accepted names with this port, for messages. */
    String describe(int port) {
        return String.join(", ", names.stream().map(n -> n.lastIndexOf(':') > n.lastIndexOf(']') ? n : n + ":" + port)
                .toList());
    }
}
