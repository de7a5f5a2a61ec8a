package eu.brain.iot.edge.rest;

import java.io.IOException;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;

import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.log.Logger;
import org.osgi.service.log.LoggerFactory;
import org.osgi.service.metatype.annotations.Designate;
import org.osgi.service.servlet.whiteboard.propertytypes.HttpWhiteboardServletAsyncSupported;
import org.osgi.service.servlet.whiteboard.propertytypes.HttpWhiteboardServletName;
import org.osgi.service.servlet.whiteboard.propertytypes.HttpWhiteboardServletPattern;

import eu.brain.iot.edge.model.api.DeviceModel;
import jakarta.servlet.Filter;
import jakarta.servlet.Servlet;
import jakarta.servlet.http.HttpServlet;
import jakarta.servlet.http.HttpServletRequest;
import jakarta.servlet.http.HttpServletResponse;

/**
 * The edge's northbound REST API in the sensiNact manner, on the OSGi Servlet Whiteboard: providers, services and
 * resources to read ({@link Reads}), actions to run ({@link Acts}). Changes are streamed by {@link SubscribeServlet}.
 * This class only routes: path first (404), then method (405), then the handler; whatever goes wrong is answered
 * as JSON {@code {"error", "status"}}.
 */
@Component(service = Servlet.class, configurationPid = RestConfig.PID)
@Designate(ocd = RestConfig.class)
@HttpWhiteboardServletName("eu.brain.iot.edge.rest")
@HttpWhiteboardServletPattern(Route.ROOT + "/*")
@HttpWhiteboardServletAsyncSupported // ACT waits for the device without holding a container thread
public final class SensinactServlet extends HttpServlet {
    private static final long serialVersionUID = 1L;

    private final transient Reads reads;
    private final transient Acts acts;
    private final transient Logger log;
    /** Body deadlines of ACTs; never waits on anything. */
    private final transient ScheduledExecutorService timer = Executors.newSingleThreadScheduledExecutor(r -> {
        Thread t = new Thread(r, "edge-rest-timer");
        t.setDaemon(true);
        return t;
    });

    @Activate
    public SensinactServlet(@Reference DeviceModel model, RestConfig config,
            @Reference(service = LoggerFactory.class) Logger log,
            @Reference(target = RequestGate.TARGET) Filter gate) { // started only once the gate filters requests
        this.log = log;
        this.reads = new Reads(model);
        this.acts = new Acts(model, positive("act.timeout.ms", config.act_timeout_ms()),
                (int) positive("act.max.body.bytes", config.act_max_body_bytes()),
                positive("act.body.timeout.ms", config.act_body_timeout_ms()), timer, log);
    }

    @Deactivate
    void deactivate() {
        timer.shutdownNow();
    }

    static long positive(String property, long value) {
        if (value <= 0) {
            throw new IllegalArgumentException("configuration " + RestConfig.PID + ": " + property
                    + " must be positive, found " + value);
        }
        return value;
    }

    @Override
    protected void service(HttpServletRequest req, HttpServletResponse resp) throws IOException {
        try {
            RequestGate.requirePassed(req);
            Route route = Route.parse(req.getPathInfo());
            route.checkMethod(req.getMethod());
            if (route.kind() == Route.Kind.ACT) {
                acts.act(route, req, resp);
            } else {
                Replies.json(resp, 200, reads.read(route));
            }
        } catch (HttpError e) {
            Replies.error(resp, e);
        } catch (IOException e) {
            throw e; // the connection failed: nobody to answer
        } catch (RuntimeException e) {
            // A bug of ours: the log gets the stack trace, the caller a short message.
            log.error("internal error on " + req.getMethod() + " " + req.getRequestURI(), e);
            if (!resp.isCommitted()) {
                Replies.error(resp, new HttpError(500, "internal error of the edge (" + e.getClass().getSimpleName()
                        + "); the node's log (Gogo: log error) has the details"));
            }
        }
    }
}
