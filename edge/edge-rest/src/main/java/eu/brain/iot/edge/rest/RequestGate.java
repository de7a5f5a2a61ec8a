package eu.brain.iot.edge.rest;

import java.io.IOException;
import java.net.InetAddress;
import java.net.UnknownHostException;
import java.time.Duration;
import java.util.Locale;

import org.osgi.framework.BundleContext;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.log.Logger;
import org.osgi.service.log.LoggerFactory;
import org.osgi.service.servlet.whiteboard.propertytypes.HttpWhiteboardFilterAsyncSupported;
import org.osgi.service.servlet.whiteboard.propertytypes.HttpWhiteboardFilterName;
import org.osgi.service.servlet.whiteboard.propertytypes.HttpWhiteboardFilterPattern;

import eu.brain.iot.edge.rest.api.AccessGate;
import jakarta.servlet.Filter;
import jakarta.servlet.FilterChain;
import jakarta.servlet.ServletException;
import jakarta.servlet.ServletRequest;
import jakarta.servlet.ServletResponse;
import jakarta.servlet.http.Cookie;
import jakarta.servlet.http.HttpServletRequest;
import jakarta.servlet.http.HttpServletResponse;

/**
 * The gate in front of every {@code /sensinact} request, so that neither a web page open in a browser nor, when the
 * API is exposed, another machine can reach the fleet uninvited. In order: {@code Host} must name this server (421:
 * DNS rebinding), {@code Origin} must be absent or this server (403: cross-site requests), the caller must be
 * authenticated when the API is exposed (401), and a POST (an ACT, a session) must say {@code Content-Type:
 * application/json} (415: a page cannot send that type across origins without a preflight, which is never granted). It also serves
 * {@code /sensinact/session}, which turns the token into a browser's session cookie ({@link Sessions}). The node's
 * other web parts (the dashboard) ask it about their requests as the {@link AccessGate} service: one gate, one token,
 * one session cookie for the whole node.
 * <p>
 * Threads: container threads, any number at once; every field is immutable after activation or thread-safe.
 */
@Component(service = { Filter.class, AccessGate.class }, configurationPid = RestConfig.PID)
@HttpWhiteboardFilterName(RequestGate.NAME)
@HttpWhiteboardFilterPattern({ Route.ROOT, Route.ROOT + "/*" })
@HttpWhiteboardFilterAsyncSupported // the servlets behind it answer asynchronously
public final class RequestGate implements Filter, AccessGate {

    static final String SESSION = AccessGate.SESSION_PATH;
    static final String NAME = "eu.brain.iot.edge.rest.gate";
    /** The filter's property, for the servlets' reference: they start only once the gate is there. */
    static final String TARGET = "(osgi.http.whiteboard.filter.name=" + NAME + ")";
    /** Request attribute: the request passed this gate. */
    private static final String PASSED = RequestGate.class.getName() + ".passed";

    private final HostNames hosts;
    private final String bind;
    private final boolean authRequired;
    /** The token when authentication is required and the token could be read; else {@code null}. */
    private final ApiToken token;
    /** Why the API refuses every request (authentication required but no usable token), else {@code null}. */
    private final String refusal;
    private final Sessions sessions;

    @Activate
    public RequestGate(BundleContext context, RestConfig config,
            @Reference(service = LoggerFactory.class) Logger log) {
        bind = context.getProperty("org.apache.felix.http.host");
        hosts = new HostNames(bind, config.allowed_hosts());
        sessions = new Sessions(Duration.ofSeconds(SensinactServlet.positive("session.max.age.s",
                config.session_max_age_s())));
        authRequired = AuthMode.of(config.auth(), log).tokenRequired(loopback(bind));
        ApiToken t = null;
        String refused = null;
        if (authRequired) {
            java.nio.file.Path file = ApiToken.file(config.api_token_file(), context.getProperty("fabric.node.name"));
            try {
                t = ApiToken.loadOrCreate(file, created -> announce(file, created));
                log.info("the edge's REST API is bound to " + where() + ": requests need the API token kept in "
                        + file);
            } catch (IllegalStateException e) {
                refused = "the edge's REST API is bound to " + where() + " and so requires authentication, but "
                        + e.getMessage() + ". Until then it refuses every request; or bind it to loopback "
                        + "(-Dorg.apache.felix.http.host=127.0.0.1)";
                log.error(refused);
            }
        }
        token = t;
        refusal = refused;
    }

    private String where() {
        return bind == null || bind.isBlank() ? "every interface" : bind;
    }

    /** The only time the token is shown: on the console of the node that made it. */
    private void announce(java.nio.file.Path file, String created) {
        System.out.println("The edge's REST API is bound to " + where() + " and requires authentication.\n"
                + "  New API token (shown once; kept in " + file + ", mode 600):\n    " + created + "\n"
                + "  Send it as 'Authorization: Bearer <token>'; browsers: POST " + SESSION + " with it for a cookie.");
    }

    /** Whether Felix HTTP binds loopback only; nothing (every interface) or a name that does not resolve is not. */
    static boolean loopback(String bindHost) {
        if (bindHost == null || bindHost.isBlank()) {
            return false;
        }
        try {
            for (InetAddress a : InetAddress.getAllByName(bindHost.strip())) {
                if (!a.isLoopbackAddress()) {
                    return false;
                }
            }
            return true;
        } catch (UnknownHostException e) {
            return false;
        }
    }

    @Override
    public void doFilter(ServletRequest request, ServletResponse response, FilterChain chain)
            throws IOException, ServletException {
        HttpServletRequest req = (HttpServletRequest) request;
        HttpServletResponse resp = (HttpServletResponse) response;
        try {
            check(req);
            req.setAttribute(PASSED, Boolean.TRUE);
            if (SESSION.equals(req.getRequestURI())) {
                session(req, resp);
                return;
            }
        } catch (HttpError e) {
            Replies.error(resp, e);
            return;
        }
        chain.doFilter(req, resp);
    }

    /**
     * Fails closed: a request that reached a servlet without passing the gate (a moment while the components
     * restart after a configuration change, the filter gone before the servlets) is answered 503, never served.
     *
     * @throws HttpError 503
     */
    static void requirePassed(HttpServletRequest req) {
        if (req.getAttribute(PASSED) == null) {
            throw new HttpError(503, "the edge's REST API is (re)starting; try again in a moment");
        }
    }

    @Override
    public Refusal check(HttpServletRequest request, boolean authenticate) {
        try {
            enforce(request, authenticate, false); // the caller's resources say what they accept
            return null;
        } catch (HttpError e) {
            return new Refusal(e.status, e.field, e.getMessage());
        }
    }

    private void check(HttpServletRequest req) {
        enforce(req, true, true);
    }

    private void enforce(HttpServletRequest req, boolean authenticate, boolean jsonPosts) {
        if (refusal != null) {
            throw new HttpError(503, refusal);
        }
        int port = req.getLocalPort();
        once(req, "Host");
        once(req, "Origin");
        String host = req.getHeader("Host");
        if (!hosts.accepts(host, port)) {
            throw HttpError.about(421, "Host", "Host '" + Echo.cut(host) + "' is not a name of this server (accepted: "
                    + hosts.describe(port) + "; configuration allowed.hosts of " + RestConfig.PID + " adds names)");
        }
        String origin = req.getHeader("Origin");
        if (origin != null && !hosts.acceptsOrigin(origin, port)) {
            throw HttpError.about(403, "Origin", "cross-origin request refused: Origin '" + Echo.cut(origin) + "' is not this "
                    + "server (accepted: no Origin, or http:// and one of " + hosts.describe(port) + ")");
        }
        if (authenticate && authRequired && !authenticated(req)) {
            throw HttpError.about(401, "Authorization", "this API is bound to " + where() + " and needs its token: "
                    + "send 'Authorization: Bearer <token>' (the token is in " + token.file + " on the node); "
                    + "a browser first POSTs " + SESSION + " with it and then uses the session cookie");
        }
        // POST is the API's one state change, and the one a page may send cross-site without a preflight (the
        // others, PUT, PATCH, DELETE, need one, which is never granted: they meet 405 or the session's DELETE)
        if (jsonPosts && req.getMethod().equals("POST") && !json(req.getContentType())) {
            throw HttpError.about(415, "Content-Type", req.getMethod() + " needs Content-Type: application/json, found "
                    + (req.getContentType() == null ? "none" : "'" + req.getContentType() + "'")
                    + " (with curl: -H 'Content-Type: application/json')");
        }
    }

    /**
     * A header this gate decides on must come at most once: with two, a server and a proxy or browser in front of
     * it could each read another one.
     */
    private static void once(HttpServletRequest req, String header) {
        java.util.Enumeration<String> values = req.getHeaders(header);
        int count = 0;
        while (values != null && values.hasMoreElements()) {
            values.nextElement();
            count++;
        }
        if (count > 1) {
            throw HttpError.closing(400, header, "the request has " + count + " " + header + " headers; send one");
        }
    }

    private static boolean json(String contentType) {
        if (contentType == null) {
            return false;
        }
        int semicolon = contentType.indexOf(';');
        String type = (semicolon < 0 ? contentType : contentType.substring(0, semicolon)).strip();
        return type.toLowerCase(Locale.ROOT).equals("application/json");
    }

    private boolean authenticated(HttpServletRequest req) {
        String authorization = req.getHeader("Authorization");
        if (authorization != null && authorization.regionMatches(true, 0, "Bearer ", 0, 7)) {
            return token.matches(authorization.substring(7));
        }
        return sessions.valid(sessionId(req));
    }

    private static String sessionId(HttpServletRequest req) {
        Cookie[] cookies = req.getCookies();
        if (cookies != null) {
            for (Cookie c : cookies) {
                if (Sessions.COOKIE.equals(c.getName())) {
                    return c.getValue();
                }
            }
        }
        return null;
    }

    /** POST opens a session (the caller is authenticated already), DELETE ends it. */
    private void session(HttpServletRequest req, HttpServletResponse resp) throws IOException {
        java.util.Map<String, Object> body = new java.util.LinkedHashMap<>();
        switch (req.getMethod()) {
            case "POST" -> {
                String id = sessions.open();
                resp.addHeader("Set-Cookie", sessions.cookie(id, false));
                body.put("session", "opened: the cookie " + Sessions.COOKIE + " authenticates this browser on "
                        + "the whole node (" + Route.ROOT + ", /dashboard)" + (authRequired ? "" : " (not needed while the API is bound to loopback)"));
            }
            case "DELETE" -> {
                sessions.close(sessionId(req));
                resp.addHeader("Set-Cookie", sessions.cookie("", true));
                body.put("session", "closed");
            }
            default -> throw HttpError.methodNotAllowed(req.getMethod(), SESSION, "POST, DELETE",
                    "POST with the token opens a browser session, DELETE ends it");
        }
        body.put("status", 200);
        Replies.json(resp, 200, body);
    }
}
