package eu.brain.iot.node;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * What the node's console shows of its bundles' logs without a shell: the edge's warnings and information (OSGi log
 * service, printed by the node's ConsoleLog), at the level the framework property sets, and Jetty's warnings (slf4j,
 * on the framework's class path), with no slf4j complaint about a missing provider.
 */
class NodeLogTest {

    private static final String EDGE = "eu.brain.iot.edge.impl.EdgeComponent - ";
    private static final String UNREACHABLE = " WARN " + EDGE + "cannot list the fleet at ";
    private static final String POLLING = " INFO " + EDGE + "edge polling the fleet at ";

    @TempDir
    Path configDir;

    @Test
    void theEdgesWarningsAndInformationReachTheConsoleWithoutAShell() throws Exception {
        try (Socket noFleet = closedPort(); NodeProcess node = start()) {
            String output = node.awaitOutput(UNREACHABLE);
            assertThat(output).contains(POLLING + fleetUrl(noFleet.getLocalPort()))
                    .containsPattern("\\d\\d:\\d\\d:\\d\\d\\.\\d{3}" + UNREACHABLE)
                    .as("framework events stay out of the console").doesNotContain("BundleEvent")
                    .doesNotContain("SLF4J");
        }
    }

    /**
     * The edge starts once per boot: one "edge polling the fleet" line once every level is up. (As a delayed
     * component it was built for its first user, disposed of when that user let go, and built again.)
     */
    @Test
    void theEdgeStartsOncePerBoot() throws Exception {
        try (Socket noFleet = closedPort(); NodeProcess node = start()) {
            node.awaitOutput("fabric node: start levels 1 and 2 up in ");
            await("no second start").during(Duration.ofSeconds(1)).atMost(Duration.ofSeconds(3))
                    .until(() -> node.output().split(POLLING, -1).length - 1 == 1);
        }
    }

    /**
     * With the simulated fleet (robot-sim's jar, built before the node): a robot taken offline is reported unreachable
     * (WARN), and its recovery at INFO, both on the console.
     */
    @Test
    void aRobotsLossAndRecoveryReachTheConsole() throws Exception {
        Path simJar = Path.of("..", "robot-sim", "target", "robot-sim.jar");
        assertThat(simJar).as("robot-sim's jar, built before the node by 'mvn -pl node -am verify'").isRegularFile();
        int simPort = NodeProcess.freePort();
        Process sim = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-jar",
                simJar.toString(), "--port", String.valueOf(simPort)).redirectErrorStream(true)
                .redirectOutput(configDir.resolve("robot-sim.log").toFile()).start();
        try {
            await("robot-sim listening").atMost(NodeProcess.DEADLINE).pollInterval(Duration.ofMillis(100))
                    .until(() -> Files.readString(configDir.resolve("robot-sim.log")).contains("listening on"));
            Files.writeString(configDir.resolve("eu.brain.iot.edge.cfg"), "fleet.url=" + fleetUrl(simPort) + "\n");
            try (NodeProcess node = start()) {
                node.awaitOutput(" INFO " + EDGE + "fleet at " + fleetUrl(simPort));
                HttpClient http = HttpClient.newHttpClient();
                URI fault = URI.create(fleetUrl(simPort) + "admin/faults/robot1");
                http.send(HttpRequest.newBuilder(fault).header("Content-Type", "application/json")
                        .POST(HttpRequest.BodyPublishers.ofString("{\"offline\":true}")).build(),
                        HttpResponse.BodyHandlers.discarding());
                node.awaitOutput(" WARN " + EDGE + "robot robot1 is unreachable after ");
                http.send(HttpRequest.newBuilder(fault).header("Content-Type", "application/json").DELETE().build(),
                        HttpResponse.BodyHandlers.discarding());
                assertThat(node.awaitOutput(" INFO " + EDGE + "robot robot1 answers again after "))
                        .containsPattern("\\d{3} INFO " + EDGE + "robot robot1 answers again after \\d+ ms");
            }
        } finally {
            sim.destroy();
            sim.waitFor();
        }
    }

    @Test
    void theLogLevelPropertyLeavesOutInformation() throws Exception {
        try (Socket noFleet = closedPort();
                NodeProcess node = start("-Dorg.osgi.service.log.admin.loglevel=WARN")) {
            assertThat(node.awaitOutput(UNREACHABLE)).doesNotContain(POLLING);
        }
    }

    @Test
    void jettysLogReachesTheConsole() throws Exception {
        try (ServerSocket taken = new ServerSocket(0, 1, InetAddress.getLoopbackAddress());
                NodeProcess node = NodeProcess.start("-Dgosh.args=--nointeractive",
                        "-Dfelix.fileinstall.dir=" + configDir, "-Dorg.osgi.service.http.port=" + taken.getLocalPort(),
                        "-Dorg.slf4j.simpleLogger.log.org.eclipse.jetty.server.Server=info")) {
            // Felix HTTP's error about the port, then Jetty's own line at the level asked for (slf4j-simple)
            assertThat(node.awaitOutput("Address already in use"))
                    .containsPattern("\\d\\d:\\d\\d:\\d\\d\\.\\d{3} ERROR org\\.apache\\.felix\\.http - "
                            + "Failed to start "
                            + "Connector")
                    .containsPattern("\\d{3} INFO org\\.eclipse\\.jetty\\.server\\.Server - jetty-11")
                    .doesNotContain("SLF4J");
        }
    }

    /** A node without a shell whose edge polls a port where nothing listens (a socket bound, never accepting). */
    private NodeProcess start(String... more) throws Exception {
        return NodeProcess.start(concat(more, "-Dgosh.args=--nointeractive", "-Dfelix.fileinstall.dir=" + configDir,
                "-Dorg.osgi.service.http.port=" + NodeProcess.freePort()));
    }

    private Socket closedPort() throws Exception {
        // a client socket bound and never connected nor listening: connections to its port are refused, and no other
        // test's or user's fleet can take the port meanwhile
        Socket socket = new Socket();
        socket.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0));
        Files.writeString(configDir.resolve("eu.brain.iot.edge.cfg"),
                "fleet.url=" + fleetUrl(socket.getLocalPort()) + "\n");
        return socket;
    }

    private static String fleetUrl(int port) {
        return "http://127.0.0.1:" + port + "/";
    }

    private static String[] concat(String[] more, String... base) {
        String[] all = new String[base.length + more.length];
        System.arraycopy(base, 0, all, 0, base.length);
        System.arraycopy(more, 0, all, base.length, more.length);
        return all;
    }

}
