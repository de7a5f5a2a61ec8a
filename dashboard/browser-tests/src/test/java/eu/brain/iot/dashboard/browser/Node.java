package eu.brain.iot.dashboard.browser;

import static org.awaitility.Awaitility.await;

import java.io.IOException;
import java.io.InputStreamReader;
import java.io.Reader;
import java.net.ServerSocket;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * The real fabric node (node/target/fabric-node.jar) in its own JVM, as a user runs it, configured to poll a given
 * fleet; it can be stopped (SIGTERM) and started again on the same port and storage, as a person restarting it
 * would. Output (stdout and stderr merged) is collected by a reader thread; {@link #output} is guarded by itself.
 */
final class Node implements AutoCloseable {

    static final Path ROOT = Path.of(System.getProperty("fabric.root", "../..")).toAbsolutePath().normalize();
    static final Path JAR = ROOT.resolve("node/target/fabric-node.jar");
    static final Duration START_DEADLINE = Duration.ofSeconds(90);
    private static final HttpClient HTTP = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(2)).build();

    private final Path home;
    private final int port;
    private final StringBuilder output = new StringBuilder();
    private Process process;
    private boolean shell;
    /** Whether the node requires its token: it is up once its dashboard refuses a request without one. */
    private boolean exposed;

    /**
     * @param home   a folder of the test's: the node's configuration and framework storage go there
     * @param fleet  the fleet's base URL (robot-sim), for the edge
     * @param behaviours whether the node installs behaviours on demand (the project's repository, as
     *        node/config does); without, no behaviour ever drives the fleet
     */
    Node(Path home, URI fleet, long pollPeriodMs, boolean behaviours) throws IOException {
        if (!Files.isRegularFile(JAR)) {
            throw new IllegalStateException(JAR + " is missing: build the node first (mvn -B -pl node -am package)");
        }
        this.home = home;
        this.port = freePort();
        Path config = Files.createDirectories(home.resolve("config"));
        Files.writeString(config.resolve("eu.brain.iot.edge.cfg"),
                "fleet.url=" + fleet + "\npoll.period.ms=" + pollPeriodMs + "\n");
        if (behaviours) {
            Files.writeString(config.resolve("eu.brain.iot.bis.cfg"),
                    Files.readString(ROOT.resolve("node/config/eu.brain.iot.bis.cfg")));
        }
    }

    URI dashboard() {
        return URI.create("http://127.0.0.1:" + port + "/dashboard/");
    }

    URI base() {
        return URI.create("http://127.0.0.1:" + port + "/");
    }

    /**
     * The node requires its API token, as when it is exposed beyond loopback: {@code auth=token} of the edge's REST
     * configuration (it stays on 127.0.0.1, so the test exposes nothing), with the token kept in {@code tokenFile}.
     */
    Node exposed(Path tokenFile) throws IOException {
        Files.writeString(home.resolve("config").resolve("eu.brain.iot.edge.rest.cfg"),
                "auth=token\napi.token.file=" + tokenFile + "\n");
        exposed = true;
        return this;
    }

    /**
     * The node joins a fabric (the federation's configuration, PID {@code eu.brain.iot.federation}): its name, the
     * broker, the fabric's key file, a state folder in its home, and a keep-alive of {@code keepAliveSeconds} (a node
     * killed is declared offline by its Last Will within 1.5 of them).
     */
    Node withFabric(URI broker, String fabric, String name, Path keyFile, int keepAliveSeconds) throws IOException {
        Files.writeString(home.resolve("config").resolve("eu.brain.iot.federation.cfg"), "broker.uri=" + broker
                + "\nfabric.name=" + fabric + "\nnode.name=" + name + "\nkey.file=" + keyFile + "\nstate.dir="
                + home.resolve("federation") + "\nkeep.alive.s=" + keepAliveSeconds + "\n");
        return this;
    }

    /** The node will read Gogo commands from {@link #type} (else it runs without a shell). */
    Node withShell() {
        shell = true;
        return this;
    }

    /** Types a line into the node's Gogo shell. */
    void type(String line) throws IOException {
        process.outputWriter(StandardCharsets.UTF_8).append(line).append('\n').flush();
    }

    /** Starts the node and waits until the dashboard answers (401 when {@link #exposed}). */
    Node start() throws IOException {
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Dgosh.args=" + (shell ? "" : "--nointeractive"), "-Dfabric.node.root=" + ROOT,
                "-Dfelix.fileinstall.dir=" + home.resolve("config"),
                "-Dorg.osgi.framework.storage=" + home.resolve("felix-cache"),
                "-Dfabric.node.state=" + home.resolve("state"),
                "-Dorg.osgi.service.http.port=" + port, "-jar", JAR.toString()));
        synchronized (output) {
            output.setLength(0);
        }
        process = new ProcessBuilder(command).redirectErrorStream(true).start();
        Process p = process;
        Thread reader = new Thread(() -> collect(p), "fabric-node-output");
        reader.setDaemon(true);
        reader.start();
        await("the dashboard of the node on port " + port + " answering").atMost(START_DEADLINE)
                .pollInterval(Duration.ofMillis(200))
                .failFast("the node exited; its output:\n" + output(), () -> !p.isAlive())
                .until(() -> status(base().resolve("dashboard/api/snapshot")) == (exposed ? 401 : 200));
        return this;
    }

    /** Stops the node as {@code kill <pid>} does, and waits for its JVM to end. */
    void stop() throws InterruptedException {
        process.destroy();
        if (!process.waitFor(30, TimeUnit.SECONDS)) {
            process.destroyForcibly().waitFor(10, TimeUnit.SECONDS);
        }
    }

    /** Kills the node as {@code kill -9 <pid>} does (nothing said to anyone), and waits for its JVM to end. */
    void kill() throws InterruptedException {
        process.destroyForcibly().waitFor(30, TimeUnit.SECONDS);
    }

    /** POSTs a JSON body to a path of the node, returns the answer's body. */
    String post(String path, String json) throws IOException, InterruptedException {
        HttpRequest request = HttpRequest.newBuilder(base().resolve(path)).timeout(Duration.ofSeconds(20))
                .header("Content-Type", "application/json").POST(HttpRequest.BodyPublishers.ofString(json)).build();
        return HTTP.send(request, HttpResponse.BodyHandlers.ofString()).body();
    }

    static int status(URI uri) {
        try {
            return HTTP.send(HttpRequest.newBuilder(uri).timeout(Duration.ofSeconds(5)).build(),
                    HttpResponse.BodyHandlers.discarding()).statusCode();
        } catch (IOException e) {
            return -1;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return -1;
        }
    }

    String output() {
        synchronized (output) {
            return output.toString();
        }
    }

    @Override
    public void close() throws InterruptedException {
        if (process != null && process.isAlive()) {
            stop();
        }
    }

    private void collect(Process p) {
        char[] buffer = new char[4096];
        try (Reader in = new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8)) {
            for (int n; (n = in.read(buffer)) >= 0;) {
                synchronized (output) {
                    output.append(buffer, 0, n);
                }
            }
        } catch (IOException e) {
            // the process ended
        }
    }

    private static int freePort() throws IOException {
        try (ServerSocket s = new ServerSocket(0)) {
            return s.getLocalPort();
        }
    }
}
