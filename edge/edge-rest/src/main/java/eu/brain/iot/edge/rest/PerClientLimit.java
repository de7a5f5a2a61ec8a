package eu.brain.iot.edge.rest;

import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.SocketAddress;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicInteger;

import org.eclipse.jetty.io.Connection;
import org.osgi.service.log.Logger;

/**
 * At most {@code max} open connections per client address (Jetty 11 has a limit in total only): a connection over
 * the limit is closed as soon as it opens, so that one client cannot take every connection. The first refusal for
 * an address is logged at warn, later ones not until its count drops below the limit again.
 * <p>
 * {@code 127.0.0.1} and {@code ::1} are not limited: every program on this machine (curl, a browser showing the
 * dashboard, a script) connects from them, so a limit there would let one local program that holds slow requests
 * lock every other one out; the total limit ({@code max.connections}) still bounds them. Other addresses, remote
 * clients (and {@code 127.0.0.2} etc. for tests), are limited.
 * <p>
 * Threads: Jetty's selector threads, any number at once; the counts are concurrent.
 */
final class PerClientLimit implements Connection.Listener {

    private final int max;
    private final Logger log;
    private final Map<InetAddress, AtomicInteger> open = new ConcurrentHashMap<>();
    private final Map<InetAddress, Boolean> warned = new ConcurrentHashMap<>();
    /** The address of each open connection: once closed, its end point no longer tells. */
    private final Map<Connection, InetAddress> clients = new ConcurrentHashMap<>();

    PerClientLimit(int max, Logger log) {
        this.max = max;
        this.log = log;
    }

    @Override
    public void onOpened(Connection connection) {
        InetAddress client = client(connection);
        if (client == null || isThisMachinesOwn(client)) {
            return;
        }
        clients.put(connection, client);
        int n = open.computeIfAbsent(client, c -> new AtomicInteger()).incrementAndGet();
        if (n > max) {
            if (warned.putIfAbsent(client, Boolean.TRUE) == null) {
                log.warn("client " + client.getHostAddress() + " has " + max + " connections open to the edge's "
                        + "REST API (max.connections.per.client): closing its new ones until some close");
            }
            connection.close();
        }
    }

    @Override
    public void onClosed(Connection connection) {
        InetAddress client = clients.remove(connection);
        if (client == null) {
            return;
        }
        AtomicInteger n = open.get(client);
        if (n != null && n.decrementAndGet() < max) {
            warned.remove(client);
            open.computeIfPresent(client, (c, count) -> count.get() <= 0 ? null : count);
        }
    }

    private static boolean isThisMachinesOwn(InetAddress a) {
        byte[] b = a.getAddress();
        return b.length == 4 ? b[0] == 127 && b[1] == 0 && b[2] == 0 && b[3] == 1 : a.isLoopbackAddress();
    }

    private static InetAddress client(Connection connection) {
        SocketAddress a = connection.getEndPoint().getRemoteSocketAddress();
        return a instanceof InetSocketAddress i ? i.getAddress() : null;
    }
}
