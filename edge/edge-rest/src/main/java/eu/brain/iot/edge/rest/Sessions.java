package eu.brain.iot.edge.rest;

import java.security.SecureRandom;
import java.time.Duration;
import java.util.Base64;
import java.util.Iterator;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/**
 * Browser sessions: a browser cannot put a bearer token on an {@code EventSource}, so {@code POST /sensinact/session}
 * with the token gives it a random session id in an HttpOnly, SameSite=Strict cookie, accepted by every endpoint
 * until it expires. Its path is {@code /}: the same session authenticates the node's other web parts (the dashboard,
 * through {@link eu.brain.iot.edge.rest.api.AccessGate}). Kept in memory (a restart logs browsers out); at most {@value #MAX} at once, the expired ones
 * dropped first, then the oldest.
 * <p>
 * Threads: any container thread; the map is concurrent and each operation stands alone.
 */
final class Sessions {

    static final String COOKIE = "brain-iot-session";
    static final int MAX = 1_000;

    private final SecureRandom random = new SecureRandom();
    private final Map<String, Long> expiry = new ConcurrentHashMap<>();
    private final Duration maxAge;

    Sessions(Duration maxAge) {
        this.maxAge = maxAge;
    }

    /** A new session; its id goes into the cookie. */
    String open() {
        if (expiry.size() >= MAX) {
            evict();
        }
        byte[] bytes = new byte[32];
        random.nextBytes(bytes);
        String id = Base64.getUrlEncoder().withoutPadding().encodeToString(bytes);
        expiry.put(id, System.nanoTime() + maxAge.toNanos());
        return id;
    }

    boolean valid(String id) {
        Long until = id == null ? null : expiry.get(id);
        if (until == null) {
            return false;
        }
        if (System.nanoTime() - until > 0) {
            expiry.remove(id);
            return false;
        }
        return true;
    }

    void close(String id) {
        if (id != null) {
            expiry.remove(id);
        }
    }

    /** The Set-Cookie value of a session (empty id and age 0: the cookie is removed). */
    String cookie(String id, boolean remove) {
        return COOKIE + "=" + (remove ? "" : id) + "; Path=/; Max-Age="
                + (remove ? 0 : maxAge.toSeconds()) + "; HttpOnly; SameSite=Strict";
    }

    private void evict() {
        long now = System.nanoTime();
        expiry.values().removeIf(until -> now - until > 0);
        Iterator<Map.Entry<String, Long>> oldest = expiry.entrySet().stream()
                .sorted(Map.Entry.comparingByValue()).iterator();
        while (expiry.size() >= MAX && oldest.hasNext()) {
            expiry.remove(oldest.next().getKey());
        }
    }
}
