package eu.brain.iot.scenario;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.URI;
import java.time.Duration;

/**
 * Whether anything answers at the broker a run's nodes are to join ({@code --broker}), checked once before they
 * start: a broker that is not there would otherwise show only as nodes whose edges never own their devices, the
 * cause in their logs. A TCP connection, closed at once: the nodes say whether the broker takes them (credentials,
 * TLS, the MQTT version).
 */
final class BrokerReach {

    /** How long the connection may take. */
    static final Duration TIMEOUT = Duration.ofSeconds(3);

    private BrokerReach() {
    }

    /** @throws IOException saying which broker does not answer, why, and what to do */
    static void check(String brokerUri) throws IOException {
        URI uri = URI.create(brokerUri);
        try (Socket s = new Socket()) {
            s.connect(new InetSocketAddress(uri.getHost(), uri.getPort()), (int) TIMEOUT.toMillis());
        } catch (IOException e) {
            throw new IOException("--broker " + brokerUri + ": nothing answers at " + uri.getHost() + ":"
                    + uri.getPort() + " (" + e.getMessage() + ", within " + TIMEOUT.toSeconds() + " s): start the "
                    + "broker there, or leave --broker out for the embedded one", e);
        }
    }
}
