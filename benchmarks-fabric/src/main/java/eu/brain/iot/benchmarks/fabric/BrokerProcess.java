package eu.brain.iot.benchmarks.fabric;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * A broker the benchmark starts in a process of its own on a free port of 127.0.0.1, with a fresh state folder:
 * the embedded broker ({@code broker/target/broker.jar}, in memory as {@code ./fabric-node --nodes} runs it, or
 * with file persistence, its own default) or Debian's Mosquitto (no persistence, its default; {@link #MAX_QUEUED};
 * Nagle's algorithm off). Stopped by {@link #close}.
 */
final class BrokerProcess implements AutoCloseable {
    private static final long START_TIMEOUT_S = 60;
    /**
     * Messages Mosquitto queues per client before it drops new ones (its default, 1,000, drops QoS 1 messages as soon
     * as a subscriber falls behind a flood): the embedded broker's default, so both are measured carrying everything.
     */
    static final int MAX_QUEUED = 100_000;

    private final String name;
    private final Process process;
    private final BrokerAddress address;

    private BrokerProcess(String name, Process process, BrokerAddress address) {
        this.name = name;
        this.process = process;
        this.address = address;
    }

    /**
     * @param inMemory sessions and queued messages in memory only (the broker's {@code --in-memory}), else in files
     *        under the state folder
     */
    static BrokerProcess embedded(Path root, Path work, boolean inMemory) throws IOException, InterruptedException {
        Path jar = root.resolve("broker/target/broker.jar");
        if (!Files.isRegularFile(jar)) {
            throw new IOException(jar + " does not exist: build it (mvn -B -pl broker package -DskipTests)");
        }
        int port = freePort();
        String folder = inMemory ? "embedded-broker" : "embedded-broker-file";
        Path data = Files.createDirectories(work.resolve(folder));
        Path java = Path.of(System.getProperty("java.home"), "bin", "java");
        List<String> command = new ArrayList<>(List.of(java.toString(), "-jar", jar.toString(), "--port",
                String.valueOf(port), "--data", data.toString()));
        if (inMemory) {
            command.add("--in-memory");
        }
        Process p = new ProcessBuilder(command).redirectErrorStream(true)
                .redirectOutput(work.resolve(folder + ".log").toFile()).start();
        String kind = inMemory ? "in memory" : "file persistence";
        return started("embedded broker (HiveMQ CE 2025.5, " + kind + ")", p, port);
    }

    static BrokerProcess mosquitto(Path work) throws IOException, InterruptedException {
        Path binary = Path.of("/usr/sbin/mosquitto");
        if (!Files.isExecutable(binary)) {
            throw new IOException("no Mosquitto at " + binary + " (Debian: apt-get install mosquitto), or give "
                    + "--mosquitto-uri tcp://HOST:PORT");
        }
        int port = freePort();
        Path conf = work.resolve("mosquitto.conf");
        Files.writeString(conf, "listener " + port + " 127.0.0.1\nallow_anonymous true\npersistence false\n"
                + "max_queued_messages " + MAX_QUEUED + "\n"
                + "set_tcp_nodelay true\n"); // as federation/README.md asks: Nagle's algorithm holds small messages
        Process p = new ProcessBuilder(List.of(binary.toString(), "-c", conf.toString()))
                .redirectErrorStream(true).redirectOutput(work.resolve("mosquitto.log").toFile()).start();
        return started("Mosquitto", p, port);
    }

    private static BrokerProcess started(String name, Process p, int port) throws IOException, InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(START_TIMEOUT_S);
        while (System.nanoTime() < deadline && p.isAlive()) {
            try (Socket s = new Socket()) {
                s.connect(new InetSocketAddress("127.0.0.1", port), 1000);
                return new BrokerProcess(name, p, new BrokerAddress("127.0.0.1", port));
            } catch (IOException notYet) {
                Thread.sleep(100); // polls the port: the process gives no other sign
            }
        }
        p.destroyForcibly();
        throw new IOException(name + " did not accept connections on 127.0.0.1:" + port + " within "
                + START_TIMEOUT_S + " s" + (p.isAlive() ? "" : " (it ended)"));
    }

    static int freePort() throws IOException {
        try (ServerSocket s = new ServerSocket(0)) {
            return s.getLocalPort();
        }
    }

    String name() {
        return name;
    }

    BrokerAddress address() {
        return address;
    }

    @Override
    public void close() throws InterruptedException {
        process.destroy();
        if (!process.waitFor(30, TimeUnit.SECONDS)) {
            process.destroyForcibly().waitFor();
        }
    }
}
