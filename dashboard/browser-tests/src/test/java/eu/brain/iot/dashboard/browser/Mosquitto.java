package eu.brain.iot.dashboard.browser;

import static org.awaitility.Awaitility.await;

import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.URI;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Assumptions;

/**
 * Debian's Mosquitto (an MQTT 5 broker) in a process of its own on a free port of 127.0.0.1, anonymous, without
 * persistence: the broker two nodes of a test join. Its log goes to {@code mosquitto.log} in its folder.
 */
final class Mosquitto implements AutoCloseable {

    static final Path BINARY = Path.of("/usr/sbin/mosquitto");
    private static final Duration LISTENING = Duration.ofSeconds(30);

    private final int port;
    private final Process process;

    private Mosquitto(Path dir) throws IOException {
        Files.createDirectories(dir);
        try (ServerSocket s = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            port = s.getLocalPort();
        }
        Path conf = dir.resolve("mosquitto.conf");
        Files.writeString(conf, "listener " + port + " 127.0.0.1\nallow_anonymous true\npersistence false\n");
        process = new ProcessBuilder(BINARY.toString(), "-c", conf.toString()).redirectErrorStream(true)
                .redirectOutput(dir.resolve("mosquitto.log").toFile()).start();
        await("Mosquitto listening on port " + port).atMost(LISTENING).pollInterval(Duration.ofMillis(50))
                .failFast("Mosquitto exited; its log: " + dir.resolve("mosquitto.log"), () -> !process.isAlive())
                .until(this::listening);
    }

    /** Starts one, or skips the calling test (saying how to install it) where Mosquitto is missing. */
    static Mosquitto start(Path dir) throws IOException {
        Assumptions.assumeTrue(Files.isExecutable(BINARY), "SKIPPED: Mosquitto is not installed (" + BINARY
                + " missing): apt-get install -y mosquitto");
        return new Mosquitto(dir);
    }

    URI uri() {
        return URI.create("tcp://127.0.0.1:" + port);
    }

    private boolean listening() {
        try (Socket s = new Socket(InetAddress.getLoopbackAddress(), port)) {
            return true;
        } catch (IOException e) {
            return false;
        }
    }

    @Override
    public void close() throws InterruptedException {
        process.destroy();
        if (!process.waitFor(10, TimeUnit.SECONDS)) {
            process.destroyForcibly().waitFor(10, TimeUnit.SECONDS);
        }
    }
}
