package eu.brain.iot.dashboard;

import java.io.IOException;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;

import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.log.Logger;
import org.osgi.service.log.LoggerFactory;
import org.osgi.service.servlet.whiteboard.propertytypes.HttpWhiteboardServletAsyncSupported;
import org.osgi.service.servlet.whiteboard.propertytypes.HttpWhiteboardServletName;
import org.osgi.service.servlet.whiteboard.propertytypes.HttpWhiteboardServletPattern;

import jakarta.servlet.AsyncContext;
import jakarta.servlet.Filter;
import jakarta.servlet.Servlet;
import jakarta.servlet.http.HttpServlet;
import jakarta.servlet.http.HttpServletRequest;
import jakarta.servlet.http.HttpServletResponse;

/**
 * The page's API, read-only: {@code GET /dashboard/api/snapshot} (the whole state as JSON, with the id of the last
 * event it includes) and {@code GET /dashboard/api/stream} (Server-Sent Events: {@code snapshot} and {@code delta}
 * events with ids; a client that reconnects with {@code Last-Event-ID}, or {@code ?lastEventId=}, gets what it
 * missed, or a fresh snapshot when that is gone). Anything else is answered with a JSON error.
 */
@Component(service = Servlet.class)
@HttpWhiteboardServletName("eu.brain.iot.dashboard.api")
@HttpWhiteboardServletPattern(ApiServlet.ROOT + "/*")
@HttpWhiteboardServletAsyncSupported // a stream must not hold a container thread
public final class ApiServlet extends HttpServlet {
    private static final long serialVersionUID = 1L;
    static final String ROOT = "/dashboard/api";
    private static final String PATHS = ROOT + "/snapshot, " + ROOT + "/stream";

    private final transient Hub hub;
    private final transient Logger log;

    @Activate
    public ApiServlet(@Reference Hub hub, @Reference(service = LoggerFactory.class) Logger log,
            @Reference(target = Gate.TARGET) Filter gate) {
        this.hub = hub;
        this.log = log;
    }

    @Override
    protected void service(HttpServletRequest req, HttpServletResponse resp) throws IOException {
        if (!Gate.passed(req)) {
            Json.error(resp, 503, "the dashboard is (re)starting; try again in a moment");
            return;
        }
        String path = req.getPathInfo() == null ? "/" : req.getPathInfo();
        if (!path.equals("/snapshot") && !path.equals("/stream")) {
            Json.error(resp, 404, "no " + Json.echo(ROOT + path) + "; the dashboard's API has " + PATHS);
            return;
        }
        if (!req.getMethod().equals("GET") && !req.getMethod().equals("HEAD")) {
            resp.setHeader("Allow", "GET, HEAD");
            Json.error(resp, 405, req.getMethod() + " is not allowed on " + ROOT + path
                    + "; the dashboard's API is read-only: use GET");
            return;
        }
        if (path.equals("/snapshot")) {
            snapshot(req, resp);
        } else {
            stream(req, resp);
        }
    }

    private void snapshot(HttpServletRequest req, HttpServletResponse resp) throws IOException {
        try {
            Json.answer(resp, 200, hub.snapshot().get(10, TimeUnit.SECONDS));
        } catch (TimeoutException e) {
            Json.error(resp, 503, "the dashboard did not answer within 10 s (is the node overloaded?); try again");
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            Json.error(resp, 503, "the node is stopping");
        } catch (ExecutionException | RuntimeException e) {
            log.error("dashboard: snapshot failed on " + req.getRequestURI(), e);
            Json.error(resp, 500, "internal error of the dashboard (" + e.getClass().getSimpleName()
                    + "); the node's log (Gogo: log error) has the details");
        }
    }

    private void stream(HttpServletRequest req, HttpServletResponse resp) throws IOException {
        String last = req.getHeader("Last-Event-ID");
        if (last == null) {
            last = req.getParameter("lastEventId"); // a page that opens a new EventSource itself cannot set the header
        }
        resp.setStatus(200);
        resp.setContentType("text/event-stream");
        resp.setCharacterEncoding("UTF-8");
        resp.setHeader("Cache-Control", "no-store");
        resp.setHeader("X-Accel-Buffering", "no");
        if (req.getMethod().equals("HEAD")) {
            return; // the headers only: a stream has no length to tell
        }
        StreamLimit limit = hub.streamLimit();
        if (!limit.tryAcquire()) {
            resp.reset();
            resp.setHeader("Retry-After", "10");
            resp.setHeader("Connection", "close");
            Json.error(resp, 503, limit.refusal());
            return;
        }
        try {
            AsyncContext async = req.startAsync();
            async.setTimeout(0); // a stream has no end of its own; heartbeats find the pages that left
            hub.attach(new SseStream(async, hub.clientQueueCapacity(), s -> {
                hub.detach(s);
                limit.release(); // once: a stream ends once
            }), last);
        } catch (IOException | RuntimeException e) {
            limit.release();
            throw e;
        }
    }
}
