package eu.brain.iot.robotsim.http;

import io.netty.handler.codec.http.HttpMethod;

/** Small checks shared by the endpoint classes. */
final class Route {
    private Route() {
    }

    /**
     * Refuses a request whose method is not one of {@code allowed} with 405 and an Allow header. HEAD is allowed
     * wherever GET is.
     */
    static boolean methodIs(ServerExchange ex, HttpMethod... allowed) {
        boolean get = false;
        for (HttpMethod m : allowed) {
            if (m.equals(ex.method())) {
                return true;
            }
            get |= m.equals(HttpMethod.GET);
        }
        if (get && ex.method().equals(HttpMethod.HEAD)) {
            return true;
        }
        StringBuilder allow = new StringBuilder();
        for (HttpMethod m : allowed) {
            allow.append(allow.length() == 0 ? "" : ", ").append(m.name());
            if (m.equals(HttpMethod.GET)) {
                allow.append(", HEAD");
            }
        }
        ex.error(405, null, ex.method() + " is not allowed on " + ex.path() + " (use " + allow + ")",
                allow.toString());
        return false;
    }

    static void notFound(ServerExchange ex) {
        ex.error(404, null, "no such endpoint: " + ex.method() + " " + ex.path()
                + " (see robot-sim/README.md for the API)", null);
    }
}
