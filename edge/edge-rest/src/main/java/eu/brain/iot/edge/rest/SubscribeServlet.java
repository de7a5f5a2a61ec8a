package eu.brain.iot.edge.rest;

import java.io.IOException;
import java.util.Enumeration;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;

import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.log.Logger;
import org.osgi.service.log.LoggerFactory;
import org.osgi.service.servlet.whiteboard.propertytypes.HttpWhiteboardServletAsyncSupported;
import org.osgi.service.servlet.whiteboard.propertytypes.HttpWhiteboardServletName;
import org.osgi.service.servlet.whiteboard.propertytypes.HttpWhiteboardServletPattern;

import eu.brain.iot.edge.model.api.DeviceModel;
import eu.brain.iot.edge.model.api.ProviderSnapshot;
import jakarta.servlet.AsyncContext;
import jakarta.servlet.Filter;
import jakarta.servlet.Servlet;
import jakarta.servlet.http.HttpServlet;
import jakarta.servlet.http.HttpServletRequest;
import jakarta.servlet.http.HttpServletResponse;

/**
 * {@code GET /sensinact/subscribe[?provider=P][&service=S]}: a Server-Sent Events stream, one
 * {@code data: {resource as JSON}} event per change of the device model, until the client goes away. Each client
 * is an {@link SseClient}; one shared thread writes to all of them and sends the heartbeats.
 */
@Component(service = Servlet.class, configurationPid = RestConfig.PID)
@HttpWhiteboardServletName("eu.brain.iot.edge.rest.subscribe")
@HttpWhiteboardServletPattern(Route.ROOT + "/subscribe")
@HttpWhiteboardServletAsyncSupported // a stream must not hold a container thread
public final class SubscribeServlet extends HttpServlet {
    private static final long serialVersionUID = 1L;
    private static final List<String> PARAMETERS = List.of("provider", "service");

    private final transient DeviceModel model;
    private final transient Logger log;
    private final int capacity;
    private final long writeTimeoutMillis;
    private final transient StreamLimit streams;
    private final transient Set<SseClient> clients = ConcurrentHashMap.newKeySet();
    private final transient ScheduledExecutorService writer = Executors.newSingleThreadScheduledExecutor(r -> {
        Thread t = new Thread(r, "edge-sse");
        t.setDaemon(true);
        return t;
    });

    @Activate
    public SubscribeServlet(@Reference DeviceModel model, RestConfig config,
            @Reference(service = LoggerFactory.class) Logger log,
            @Reference(target = RequestGate.TARGET) Filter gate) { // started only once the gate filters requests
        this.model = model;
        this.log = log;
        this.capacity = (int) SensinactServlet.positive("sse.queue.capacity", config.sse_queue_capacity());
        long heartbeat = SensinactServlet.positive("sse.heartbeat.ms", config.sse_heartbeat_ms());
        this.writeTimeoutMillis = SensinactServlet.positive("sse.write.timeout.ms", config.sse_write_timeout_ms());
        this.streams = new StreamLimit((int) SensinactServlet.positive("sse.max.streams", config.sse_max_streams()),
                "the edge's SSE streams (" + Route.ROOT + "/subscribe)", "sse.max.streams of " + RestConfig.PID, log);
        writer.scheduleAtFixedRate(() -> clients.forEach(SseClient::heartbeat), heartbeat, heartbeat,
                TimeUnit.MILLISECONDS);
        // a client that stopped reading is found within a quarter of the write timeout after it expires
        long check = Math.max(10, writeTimeoutMillis / 4);
        writer.scheduleAtFixedRate(() -> clients.forEach(SseClient::checkStalled), check, check,
                TimeUnit.MILLISECONDS);
    }

    @Deactivate
    void deactivate() {
        clients.forEach(c -> c.close("the edge's REST service stops", false));
        writer.shutdown();
    }

    @Override
    protected void service(HttpServletRequest req, HttpServletResponse resp) throws IOException {
        try {
            RequestGate.requirePassed(req);
            boolean head = req.getMethod().equals("HEAD");
            if (!req.getMethod().equals("GET") && !head) {
                throw HttpError.methodNotAllowed(req.getMethod(), Echo.cut(req.getRequestURI()), "GET",
                        "a stream of changes as text/event-stream");
            }
            String provider;
            String service;
            try {
                provider = parameter(req, "provider");
                service = parameter(req, "service");
                checkQuery(req);
            } catch (HttpError e) {
                throw e;
            } catch (RuntimeException e) {
                // Jetty decodes the query lazily and throws (a BadMessageException) on bytes that are not UTF-8
                throw HttpError.about(400, "query", "the query string is not valid percent-encoded UTF-8 ("
                        + e.getMessage() + "); encode provider and service names as UTF-8, e.g. "
                        + "?provider=robot1&service=position");
            }
            if (provider != null && model.provider(provider).isEmpty()) {
                throw HttpError.notFound("no provider '" + Echo.cut(provider) + "'; providers: "
                        + model.providers().stream().map(ProviderSnapshot::id).toList());
            }
            if (head) {
                // what a GET would answer, without the stream (and without a subscription)
                resp.setStatus(200);
                resp.setContentType("text/event-stream");
                resp.setCharacterEncoding("UTF-8");
                resp.setHeader("Cache-Control", "no-store");
                return;
            }
            if (!streams.tryAcquire()) {
                resp.setHeader("Retry-After", "10");
                throw HttpError.closing(503, null, streams.refusal());
            }
            open(req, resp, provider, service);
        } catch (HttpError e) {
            Replies.error(resp, e);
        }
    }

    private void open(HttpServletRequest req, HttpServletResponse resp, String provider, String service)
            throws IOException {
        resp.setStatus(200);
        resp.setContentType("text/event-stream");
        resp.setCharacterEncoding("UTF-8");
        resp.setHeader("Cache-Control", "no-store");
        AsyncContext async = req.startAsync();
        async.setTimeout(0); // a stream has no end of its own; heartbeats find the clients that left
        String filter = "provider=" + (provider == null ? "*" : provider) + ", service="
                + (service == null ? "*" : service);
        String who = req.getRemoteAddr() + ":" + req.getRemotePort() + " (" + filter + ")";
        SseClient client;
        try {
            client = new SseClient(async, writer, capacity, writeTimeoutMillis, who, log, c -> {
                clients.remove(c);
                streams.release(); // once: SseClient calls this once, when it closes
            });
        } catch (IOException | RuntimeException e) {
            streams.release();
            throw e;
        }
        clients.add(client);
        client.start("subscribed to " + filter, listener -> model.subscribe(provider, service, listener));
        log.debug("SSE client " + who + " subscribed");
    }

    private static String parameter(HttpServletRequest req, String name) {
        String[] values = req.getParameterValues(name);
        if (values == null) {
            return null;
        }
        if (values.length > 1) {
            throw HttpError.badRequest("query parameter '" + name + "' given " + values.length
                    + " times; give it once (or leave it out for any " + name + ")");
        }
        return values[0].isBlank() ? null : values[0].strip();
    }

    private static void checkQuery(HttpServletRequest req) {
        for (Enumeration<String> names = req.getParameterNames(); names.hasMoreElements();) {
            String name = names.nextElement();
            if (!PARAMETERS.contains(name)) {
                throw HttpError.badRequest("unknown query parameter '" + Echo.cut(name) + "'; " + Route.ROOT + "/subscribe"
                        + " takes " + PARAMETERS + ", e.g. ?provider=robot1&service=position");
            }
        }
    }
}
