package eu.brain.iot.dashboard;

import java.io.IOException;

import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.servlet.whiteboard.propertytypes.HttpWhiteboardFilterAsyncSupported;
import org.osgi.service.servlet.whiteboard.propertytypes.HttpWhiteboardFilterName;
import org.osgi.service.servlet.whiteboard.propertytypes.HttpWhiteboardFilterPattern;

import eu.brain.iot.edge.rest.api.AccessGate;
import eu.brain.iot.edge.rest.api.AccessGate.Refusal;
import jakarta.servlet.Filter;
import jakarta.servlet.FilterChain;
import jakarta.servlet.ServletException;
import jakarta.servlet.ServletRequest;
import jakarta.servlet.ServletResponse;
import jakarta.servlet.http.HttpServletRequest;
import jakarta.servlet.http.HttpServletResponse;

/**
 * The node's gate in front of the dashboard: the edge's {@link AccessGate} (the same Host and Origin checks, token and
 * session cookie as {@code /sensinact}) asked about every request under {@code /dashboard}. The API
 * ({@code /dashboard/api/}) needs authentication when the node requires it; the page's static files do not (they hold
 * no data, and must load to show the login form), but pass the Host and Origin checks.
 * <p>
 * The servlets start only once this filter is registered (their reference on {@link #TARGET}), and the API refuses a
 * request that did not pass it ({@link #requirePassed}): the dashboard fails closed, never open.
 * <p>
 * Threads: container threads, any number at once; the gate is immutable and thread-safe.
 */
@Component(service = Filter.class)
@HttpWhiteboardFilterName(Gate.NAME)
@HttpWhiteboardFilterPattern({ "/dashboard", "/dashboard/*" })
@HttpWhiteboardFilterAsyncSupported // the stream answers asynchronously
public final class Gate implements Filter {

    static final String NAME = "eu.brain.iot.dashboard.gate";
    /** The filter's property, for the servlets' reference. */
    static final String TARGET = "(osgi.http.whiteboard.filter.name=" + NAME + ")";
    private static final String PASSED = Gate.class.getName() + ".passed";

    private final AccessGate gate;

    @Activate
    public Gate(@Reference AccessGate gate) {
        this.gate = gate;
    }

    @Override
    public void doFilter(ServletRequest request, ServletResponse response, FilterChain chain)
            throws IOException, ServletException {
        HttpServletRequest req = (HttpServletRequest) request;
        HttpServletResponse resp = (HttpServletResponse) response;
        String path = req.getRequestURI().substring(req.getContextPath().length());
        boolean api = path.equals(ApiServlet.ROOT) || path.startsWith(ApiServlet.ROOT + "/");
        Refusal refusal = gate.check(req, api);
        if (refusal != null) {
            if (refusal.status() == 401) {
                resp.setHeader("WWW-Authenticate", "Bearer realm=\"brain-iot edge\"");
            }
            Json.error(resp, refusal.status(), refusal.message(), refusal.field());
            return;
        }
        req.setAttribute(PASSED, Boolean.TRUE);
        chain.doFilter(req, resp);
    }

    /** Whether the request passed this gate (a request that slipped by while the components restart did not). */
    static boolean passed(HttpServletRequest req) {
        return req.getAttribute(PASSED) != null;
    }
}
