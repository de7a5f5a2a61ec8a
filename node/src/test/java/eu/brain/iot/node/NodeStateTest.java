package eu.brain.iot.node;

import static org.assertj.core.api.Assertions.assertThat;

import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * One node, one state, one port: a second node on a state folder that a running node holds refuses to start and says
 * why; a node whose HTTP port another program holds does not claim to be up, names the port, and its check fails.
 */
class NodeStateTest {

    private static final String READY = "fabric node ready in ";

    @TempDir
    Path state;
    @TempDir
    Path configDir;

    @Test
    void aSecondNodeOnTheSameStateFolderRefusesToStartAndSaysWhoHoldsIt() throws Exception {
        try (NodeProcess first = NodeProcess.start("-Dfelix.fileinstall.dir=" + configDir,
                "-Dorg.osgi.service.http.port=" + NodeProcess.freePort(), "-Dfabric.node.state=" + state)) {
            first.awaitOutput(READY);
            assertThat(Files.readString(state.resolve("node.lock"))).contains("process " + first.pid());

            try (NodeProcess second = NodeProcess.start("-Dfelix.fileinstall.dir=" + configDir,
                    "-Dorg.osgi.service.http.port=" + NodeProcess.freePort(), "-Dfabric.node.state=" + state,
                    "-Dfabric.node.exitWhenReady=true")) {
                int code = second.awaitExit();

                assertThat(code).as(second.output()).isEqualTo(1);
                assertThat(second.output()).contains("fabric node: NOT started: the state folder " + state
                        + " is in use by another node: process " + first.pid() + " (node \"node\") holds "
                        + state.resolve("node.lock")).contains("--state=DIR").contains("--name=NAME")
                        .doesNotContain(READY);
            }
        }
        // the first node ended: its lock went with it
        try (NodeProcess again = NodeProcess.start("-Dfelix.fileinstall.dir=" + configDir,
                "-Dorg.osgi.service.http.port=" + NodeProcess.freePort(), "-Dfabric.node.state=" + state,
                "-Dfabric.node.exitWhenReady=true")) {
            assertThat(again.awaitExit()).as(again.output()).isZero();
        }
    }

    @Test
    void aNodeWhoseHttpPortIsTakenSaysWhichPortAndItsCheckFails() throws Exception {
        try (ServerSocket taken = new ServerSocket(0, 1, InetAddress.getLoopbackAddress());
                NodeProcess node = NodeProcess.start("-Dfelix.fileinstall.dir=" + configDir,
                        "-Dorg.osgi.service.http.port=" + taken.getLocalPort(), "-Dfabric.node.exitWhenReady=true")) {
            int code = node.awaitExit();

            assertThat(code).as(node.output()).isEqualTo(1);
            assertThat(node.output()).contains("WITH PROBLEMS").contains("port " + taken.getLocalPort()
                    + " on 127.0.0.1 could not be bound").contains("--http-port=N")
                    .doesNotContain("dashboard: http");
        }
    }
}
