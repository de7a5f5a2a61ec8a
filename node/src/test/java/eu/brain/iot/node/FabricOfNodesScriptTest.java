package eu.brain.iot.node;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import com.fasterxml.jackson.databind.ObjectMapper;

/**
 * The README's {@code ./fabric-node --nodes=2 --fleet}, as a user runs it (the built jars; a {@code mvn} on the PATH
 * that fails, so that no build runs inside the test): the embedded broker, two nodes and robot-sim; each node's edge
 * owns its share of the robots, and robot-sim's ground truth shows each robot commanded by the node that owns it
 * (robot2 by node1, robot1 and robot3 by node2: node K owns the robots whose number is K-1 modulo 2); SIGTERM
 * stops everything, saying so.
 */
class FabricOfNodesScriptTest {

    private static final Path SCRIPT = Path.of("..", "fabric-node").toAbsolutePath().normalize();
    private static final Duration START = Duration.ofMinutes(4);
    private static final ObjectMapper JSON = new ObjectMapper();

    @TempDir
    Path dir;

    @Test
    void twoNodesShareTheFleetAndEachRobotIsCommandedByTheNodeThatOwnsIt() throws Exception {
        Path bin = failingMaven();
        int http = twoFreePorts();
        int fleet = NodeProcess.freePort();
        int broker = NodeProcess.freePort();
        Path out = dir.resolve("out.txt");
        Process fabric = start(bin, out, "--nodes=2", "--fleet", "--state=" + dir.resolve("fabric"),
                "--http-port=" + http, "--fleet-port=" + fleet, "--broker-port=" + broker);
        try {
            await("the fabric ready").atMost(START).pollInterval(Duration.ofMillis(200))
                    .failFast("the script ended", () -> !fabric.isAlive())
                    .until(() -> Files.readString(out).contains("ready:"));
            assertThat(Files.readString(dir.resolve("fabric/node2/config/eu.brain.iot.edge.cfg")))
                    .contains("share=2/2", "share.leased=true");

            HttpClient client = HttpClient.newHttpClient();
            URI world = URI.create("http://127.0.0.1:" + fleet + "/world");
            List<String> owners = List.of("robot1 node2", "robot2 node1", "robot3 node2");
            await("every robot commanded, each by its owner").atMost(START).pollInterval(Duration.ofMillis(500))
                    .failFast("the script ended", () -> !fabric.isAlive())
                    .until(() -> commanders(client, world), c -> c.size() == 3 && c.containsAll(owners));
            assertThat(Files.readString(dir.resolve("fabric/node2/node.log")))
                    .contains("for node node2, its share: 2/2");
        } finally {
            fabric.destroy(); // SIGTERM to the script: it stops the nodes, robot-sim and the broker
            boolean ended = fabric.waitFor(60, TimeUnit.SECONDS);
            if (!ended) {
                fabric.destroyForcibly();
            }
            assertThat(ended).as(Files.readString(out)).isTrue();
        }
        assertThat(fabric.exitValue()).isEqualTo(143);
        assertThat(Files.readString(out)).contains("fabric-nodes: stopping 2 node(s) and the broker",
                "fabric-nodes: stopped").doesNotContain("mvn must not run");
    }

    /**
     * A node whose HTTP server cannot listen although the script found its port free (a program took the port in
     * between; here the node is told another port, which a test socket holds, through the framework property that
     * comes after the script's own) is not reported ready: the script names the node and the port, and stops.
     */
    @Test
    void aNodeWithoutItsHttpServerIsNotReportedReady() throws Exception {
        Path bin = failingMaven();
        try (ServerSocket taken = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            Path out = dir.resolve("out.txt");
            Process fabric = start(bin, out, "--nodes=1", "--no-shell", "--state=" + dir.resolve("fabric"),
                    "--http-port=" + NodeProcess.freePort(), "--broker-port=" + NodeProcess.freePort(),
                    "-Dorg.osgi.service.http.port=" + taken.getLocalPort());
            try {
                await("the script ended").atMost(START).pollInterval(Duration.ofMillis(200))
                        .failFast("the script said the fabric is ready", () -> Files.readString(out)
                                .contains("ready:"))
                        .until(() -> !fabric.isAlive());
            } finally {
                stop(fabric);
            }
            String output = Files.readString(out);
            assertThat(fabric.exitValue()).as(output).isEqualTo(1);
            assertThat(output).contains("fabric-nodes: node1 started without its REST API and dashboard: port "
                    + taken.getLocalPort() + " of its HTTP server was taken when it started")
                    .contains("choose another with --http-port=N")
                    .doesNotContain("ready:").doesNotContain("REST http").doesNotContain("mvn must not run");
        }
    }

    /**
     * The embedded broker killed (SIGKILL) while the fabric runs: the script says so in its own words, naming the
     * broker and its exit code, without bash's job notice ("line N: PID Killed java -jar ..."), and stops the node.
     */
    @Test
    void theEmbeddedBrokerKilledIsNamedWithItsExitCode() throws Exception {
        Path bin = failingMaven();
        Path out = dir.resolve("out.txt");
        Process fabric = start(bin, out, "--nodes=1", "--no-shell", "--state=" + dir.resolve("fabric"),
                "--http-port=" + NodeProcess.freePort(), "--broker-port=" + NodeProcess.freePort());
        try {
            await("the fabric ready").atMost(START).pollInterval(Duration.ofMillis(200))
                    .failFast("the script ended", () -> !fabric.isAlive())
                    .until(() -> Files.readString(out).contains("ready:"));
            Matcher pid = Pattern.compile("embedded broker \\S+ \\(pid (\\d+),").matcher(Files.readString(out));
            assertThat(pid.find()).as(Files.readString(out)).isTrue();
            ProcessHandle broker = ProcessHandle.of(Long.parseLong(pid.group(1))).orElseThrow();
            broker.destroyForcibly();

            assertThat(fabric.waitFor(60, TimeUnit.SECONDS)).as(Files.readString(out)).isTrue();
        } finally {
            stop(fabric);
        }
        String output = Files.readString(out);
        assertThat(fabric.exitValue()).as(output).isEqualTo(1);
        assertThat(output).containsPattern("fabric-nodes: the embedded broker \\(pid \\d+, log .*broker\\.log\\) ended "
                + "\\(exit code 137, signal KILL\\); stopping the others")
                .contains("fabric-nodes: stopping 1 node(s)\n", "fabric-nodes: stopped")
                .doesNotContain("Killed").doesNotContain("mvn must not run");
    }

    /** A folder with a {@code mvn} that fails, first on the PATH: the jars are built, no build runs in a test. */
    private Path failingMaven() throws IOException {
        Path bin = Files.createDirectories(dir.resolve("bin"));
        Path mvn = bin.resolve("mvn");
        Files.writeString(mvn, "#!/bin/sh\necho 'mvn must not run here: the jars are built' >&2\nexit 3\n");
        Files.setPosixFilePermissions(mvn, PosixFilePermissions.fromString("rwxr-xr-x"));
        return bin;
    }

    /** {@code ./fabric-node} with these arguments, its output (both streams) in the file, no console. */
    private static Process start(Path bin, Path out, String... args) throws IOException {
        List<String> command = new java.util.ArrayList<>(List.of("bash", SCRIPT.toString()));
        command.addAll(List.of(args));
        ProcessBuilder builder = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(out.toFile())
                .redirectInput(ProcessBuilder.Redirect.from(new java.io.File("/dev/null")));
        builder.environment().put("PATH", bin + ":" + System.getenv("PATH"));
        return builder.start();
    }

    /** SIGTERM to the script, which stops what it started; SIGKILL when it has not ended within a minute. */
    private static void stop(Process fabric) throws InterruptedException {
        fabric.destroy();
        if (!fabric.waitFor(60, TimeUnit.SECONDS)) {
            fabric.destroyForcibly();
        }
    }

    /**
     * Per robot commanded so far, "robotN nodeK": the last node that commanded it (robot-sim's ground truth,
     * {@code commandOrigins.robots} of {@code GET /world}).
     */
    private static List<String> commanders(HttpClient client, URI world) throws IOException, InterruptedException {
        String body = client.send(HttpRequest.newBuilder(world).timeout(Duration.ofSeconds(5)).build(),
                HttpResponse.BodyHandlers.ofString()).body();
        List<String> found = new java.util.ArrayList<>();
        JSON.readTree(body).path("commandOrigins").path("robots").properties()
                .forEach(e -> found.add(e.getKey() + " " + e.getValue().path("node").asText()));
        return found;
    }

    /** A port N free now with N+1 free too (node K's REST port is N+K-1). */
    private static int twoFreePorts() throws IOException {
        for (int tries = 0; tries < 50; tries++) {
            int port = NodeProcess.freePort();
            if (port < 65535) {
                try (java.net.ServerSocket next = new java.net.ServerSocket(port + 1, 1,
                        java.net.InetAddress.getLoopbackAddress())) {
                    return port;
                } catch (IOException taken) {
                    // try another
                }
            }
        }
        throw new IOException("no two free consecutive ports on 127.0.0.1");
    }
}
