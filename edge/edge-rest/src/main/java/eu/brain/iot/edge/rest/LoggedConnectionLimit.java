package eu.brain.iot.edge.rest;

import org.eclipse.jetty.server.ConnectionLimit;
import org.eclipse.jetty.server.Connector;
import org.osgi.service.log.Logger;

/**
 * Jetty's limit on open connections, all clients together, which says when it is reached: Jetty then stops accepting
 * connections (a client waits in the kernel's backlog), and without a line in the log an operator only sees a node
 * that stopped answering. Logged at warn when the limit is reached, at info when Jetty accepts again.
 * <p>
 * Threads: Jetty calls {@link #limit()} and {@link #unlimit()} under its own lock, one at a time.
 */
final class LoggedConnectionLimit extends ConnectionLimit {

    private final Logger log;

    LoggedConnectionLimit(int max, Logger log, Connector... connectors) {
        super(max, connectors);
        this.log = log;
    }

    @Override
    protected void limit() {
        super.limit();
        log.warn("HTTP: " + getMaxConnections() + " connections open, the most allowed (max.connections of "
                + RestConfig.PID + "); no new connection is accepted until one closes");
    }

    @Override
    protected void unlimit() {
        super.unlimit();
        log.info("HTTP: below " + getMaxConnections() + " open connections again; new connections are accepted");
    }
}
