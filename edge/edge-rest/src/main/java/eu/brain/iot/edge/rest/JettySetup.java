package eu.brain.iot.edge.rest;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import org.apache.felix.http.jetty.ConnectorFactory;
import org.eclipse.jetty.server.AbstractConnector;
import org.eclipse.jetty.server.ConnectionLimit;
import org.eclipse.jetty.server.Connector;
import org.eclipse.jetty.server.HttpConfiguration;
import org.eclipse.jetty.server.HttpConnectionFactory;
import org.eclipse.jetty.server.LocalConnector;
import org.eclipse.jetty.server.Server;
import org.eclipse.jetty.server.ServerConnector;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.log.Logger;
import org.osgi.service.log.LoggerFactory;

/**
 * What Felix HTTP 5.2.2 offers no property for: JSON instead of Jetty's HTML error pages (also for the errors of its
 * request parser, 400/414/431, which no servlet error page sees), a bound on connections in total (Jetty's
 * {@link ConnectionLimit}) and one per client address ({@link PerClientLimit}), and a request handed to the API
 * once its headers are in (Jetty waits for the first body bytes by default, so an ACT declaring a body over
 * {@code act.max.body.bytes} and sending none got no 413 until the idle timeout), and a bounded send buffer on every
 * accepted connection ({@code send.buffer.bytes}: Linux grows an unset one to megabytes, which a client that stopped
 * reading fills at a few SSE changes a second only after tens of minutes, and only then does
 * {@code sse.write.timeout.ms} start counting).
 * <p>
 * Felix HTTP hands its running Jetty {@link Server} to every {@link ConnectorFactory} service (its extension point
 * for extra connectors) and only there; this component uses that call to install the above on the server and its
 * HTTP connector, and returns an in-memory {@link LocalConnector} (no socket) as the connector it must add.
 * Felix HTTP calls it again after it restarts Jetty (a new configuration).
 * <p>
 * Threads: Felix HTTP's, one call at a time (its service tracker).
 */
@Component(service = ConnectorFactory.class, configurationPid = RestConfig.PID)
public final class JettySetup implements ConnectorFactory {

    private final int maxConnections;
    private final int maxPerClient;
    private final int sendBuffer;
    private final Logger log;
    private final List<Runnable> undo = new ArrayList<>();

    @Activate
    public JettySetup(RestConfig config, @Reference(service = LoggerFactory.class) Logger log) {
        this.maxConnections = (int) SensinactServlet.positive("max.connections", config.max_connections());
        this.maxPerClient = (int) SensinactServlet.positive("max.connections.per.client",
                config.max_connections_per_client());
        if (config.send_buffer_bytes() < 0) {
            throw new IllegalArgumentException("send.buffer.bytes must be 0 (the kernel's choice) or a size in bytes, not "
                    + config.send_buffer_bytes());
        }
        this.sendBuffer = config.send_buffer_bytes();
        this.log = log;
    }

    @Override
    public synchronized Connector createConnector(Server server) {
        org.eclipse.jetty.server.handler.ErrorHandler before = server.getErrorHandler();
        server.setErrorHandler(new JsonErrorHandler());
        Connector[] network = Arrays.stream(server.getConnectors()).filter(c -> !(c instanceof LocalConnector))
                .toArray(Connector[]::new);
        ConnectionLimit total = new LoggedConnectionLimit(maxConnections, log, network);
        PerClientLimit perClient = new PerClientLimit(maxPerClient, log);
        try {
            total.start();
        } catch (Exception e) {
            log.warn("could not limit Jetty's connections to " + maxConnections + ": " + e);
        }
        List<HttpConfiguration> delayed = new ArrayList<>();
        for (Connector c : network) {
            if (c instanceof AbstractConnector a) {
                a.addBean(perClient);
            }
            if (sendBuffer > 0 && c instanceof ServerConnector s) {
                // applies to the connections it accepts from now on (ServerConnector.configure at accept)
                int kernel = s.getAcceptedSendBufferSize();
                s.setAcceptedSendBufferSize(sendBuffer);
                undo.add(() -> s.setAcceptedSendBufferSize(kernel));
            }
            HttpConnectionFactory http = c.getConnectionFactory(HttpConnectionFactory.class);
            if (http != null && http.getHttpConfiguration().isDelayDispatchUntilContent()) {
                // read per request: applies from the next request; bodies are read without a thread (BodyReader)
                http.getHttpConfiguration().setDelayDispatchUntilContent(false);
                delayed.add(http.getHttpConfiguration());
            }
        }
        undo.add(() -> {
            // Jetty keeps running when this bundle stops: it must not keep a handler of a bundle that may go away
            server.setErrorHandler(before);
            try {
                total.stop();
            } catch (Exception e) {
                log.debug("stopping the connection limit: " + e);
            }
            for (Connector c : network) {
                if (c instanceof AbstractConnector a) {
                    a.removeBean(perClient);
                }
            }
            delayed.forEach(h -> h.setDelayDispatchUntilContent(true));
        });
        log.info("Jetty: JSON error pages, at most " + maxConnections + " connections (" + maxPerClient
                + " per client address), send buffers of " + (sendBuffer > 0 ? sendBuffer + " bytes" : "the kernel's size"));
        return new LocalConnector(server);
    }

    @Deactivate
    synchronized void deactivate() {
        undo.forEach(Runnable::run); // Felix HTTP removes the LocalConnector itself
        undo.clear();
    }
}
