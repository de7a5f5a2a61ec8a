package eu.brain.iot.federation.impl;

import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.concurrent.TimeUnit;

import org.awaitility.Awaitility;

import eu.brain.iot.broker.BrokerOptions;
import eu.brain.iot.broker.BrokerOptions.Persistence;
import eu.brain.iot.broker.EmbeddedBroker;


/**
 * A real MQTT 5 broker for a test, on a free port of 127.0.0.1: Mosquitto (Debian's binary, as a process of its own)
 * or the fabric's embedded broker (HiveMQ Community Edition, broker/) in the test's JVM. Both keep no state across a restart (Mosquitto's default;
 * HiveMQ in memory), so a restart loses every queued message and session: what the fabric's end-to-end
 * acknowledgement must make up for.
 */
abstract class Broker implements AutoCloseable {

    static final Path MOSQUITTO = Path.of("/usr/sbin/mosquitto");

    enum Kind { MOSQUITTO, HIVEMQ }

    final int port;
    final Path dir;

    Broker(Path dir) throws IOException {
        this.dir = dir;
        try (ServerSocket s = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            this.port = s.getLocalPort();
        }
    }

    /**
     * @param dir the broker's folder (Mosquitto's); the embedded broker's is a new one under {@code target/} (see
     *            {@link HiveMq#close})
     */
    static Broker of(Kind kind, Path dir) throws Exception {
        Broker b = kind == Kind.MOSQUITTO ? new Mosquitto(dir)
                : new HiveMq(Files.createTempDirectory(Files.createDirectories(Path.of("target", "test-brokers")),
                        "hivemq-"));
        b.start();
        return b;
    }

    String uri() {
        return "tcp://127.0.0.1:" + port;
    }

    abstract void start() throws Exception;

    abstract void stop() throws Exception;

    void restart() throws Exception {
        stop();
        start();
    }

    /** Stops the broker at the end of a test (the embedded one in the background: see {@link HiveMq#close}). */
    @Override
    public void close() throws Exception {
        stop();
    }

    void awaitListening() {
        Awaitility.await("broker on port " + port).atMost(Duration.ofSeconds(60)).pollInterval(Duration.ofMillis(50))
                .until(() -> {
                    try (Socket s = new Socket(InetAddress.getLoopbackAddress(), port)) {
                        return true;
                    } catch (IOException e) {
                        return false;
                    }
                });
    }

    static final class Mosquitto extends Broker {
        private Process process;

        Mosquitto(Path dir) throws IOException {
            super(dir);
        }

        @Override
        void start() throws Exception {
            Path conf = dir.resolve("mosquitto.conf");
            Files.createDirectories(dir);
            Files.writeString(conf, "listener " + port + " 127.0.0.1\nallow_anonymous true\npersistence false\n");
            process = new ProcessBuilder(MOSQUITTO.toString(), "-c", conf.toString())
                    .redirectErrorStream(true).redirectOutput(dir.resolve("mosquitto.log").toFile()).start();
            awaitListening();
        }

        @Override
        void stop() throws Exception {
            if (process != null) {
                process.destroy();
                if (!process.waitFor(10, TimeUnit.SECONDS)) {
                    process.destroyForcibly().waitFor(10, TimeUnit.SECONDS);
                }
                process = null;
            }
        }
    }

    /** The fabric's own embedded broker (broker/), with no persistence and HiveMQ's default offline queue. */
    static final class HiveMq extends Broker {
        /** HiveMQ's own default per offline client: a broker that drops what an offline node was sent. */
        static final long HIVEMQ_DEFAULT_QUEUE = 1_000;
        private EmbeddedBroker broker;

        HiveMq(Path dir) throws IOException {
            super(dir);
        }

        @Override
        void start() throws Exception {
            broker = EmbeddedBroker.start(new BrokerOptions(BrokerOptions.DEFAULT_BIND, port, dir,
                    Persistence.IN_MEMORY, HIVEMQ_DEFAULT_QUEUE));
            awaitListening();
        }

        @Override
        void stop() {
            if (broker != null) {
                broker.close();
                broker = null;
            }
        }

        /**
         * At a test's end the broker stops on a thread of its own: HiveMQ's event loops each wait Netty's quiet
         * period (2 s) in turn, 4 s that no test needs to wait for (the next test's broker has a port and a folder of
         * its own; {@link #restart} still waits). Its folder is outside the test's temporary folder, which JUnit
         * deletes while the broker may still be stopping.
         */
        @Override
        public void close() {
            EmbeddedBroker stopping = broker;
            broker = null;
            if (stopping != null) {
                Thread t = new Thread(stopping::close, "test-broker-stop-" + port);
                t.setDaemon(true);
                t.start();
            }
        }
    }
}
