package eu.brain.iot.scenario;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.URI;
import java.time.Duration;

/**
 * Whether anything answers at the broker a run's nodes are to join ({@code --broker}), checked once before they
 * start: a broker that is not there would otherwise show only as nodes whose edges never own their devices, the
 * cause in their logs. A TCP connection, closed at once, tried again for up to {@link #TIMEOUT} while refused (a
 * broker started just before the run may not listen yet): the nodes say whether the broker takes them (credentials,
 * TLS, the MQTT version).
 */
final class BrokerReach {

    /** How long the broker may take to answer, every attempt included. */
    static final Duration TIMEOUT = Duration.ofSeconds(3);

    /** Pause between two attempts while the broker refuses (one started with the run may not listen yet). */
    private static final long RETRY_MILLIS = 100;

    private BrokerReach() {
    }

    /** @throws IOException saying which broker does not answer, why, and what to do */
    static void check(String brokerUri) throws IOException, InterruptedException {
        URI uri = URI.create(brokerUri);
        long deadline = System.nanoTime() + TIMEOUT.toNanos();
        while (true) {
            long left = Math.max(1, (deadline - System.nanoTime()) / 1_000_000);
            try (Socket s = new Socket()) {
                s.connect(new InetSocketAddress(uri.getHost(), uri.getPort()), (int) left);
                return;
            } catch (IOException e) {
                if (System.nanoTime() + RETRY_MILLIS * 1_000_000 >= deadline) {
                    throw new IOException("--broker " + brokerUri + ": nothing answers at " + uri.getHost() + ":"
                            + uri.getPort() + " (" + e.getMessage() + ", within " + TIMEOUT.toSeconds() + " s): "
                            + "start the broker there, or leave --broker out for the embedded one", e);
                }
                Thread.sleep(RETRY_MILLIS);
            }
        }
    }
}
