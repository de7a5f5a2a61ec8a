package eu.brain.iot.scenario;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.net.ServerSocket;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** What a node's log says kept it out of its fabric, and the broker checked before the nodes start. */
class FabricTroubleTest {

    @Test
    void theFirstLineThatSaysWhyANodeIsOutOfItsFabricWithoutTheLoggersPrefix(@TempDir Path dir) throws Exception {
        Path log = Files.writeString(dir.resolve("node.log"), """
                04:01:02.003 INFO eu.brain.iot.bis.impl.BisComponent - installed something
                04:01:02.100 WARN eu.brain.iot.federation.impl.FabricComponent - Fabric w: node node1 cannot reach \
                the broker: cannot connect to the broker tcp://127.0.0.1:9: Connection refused; trying again every \
                1000 ms
                04:01:03.100 ERROR eu.brain.iot.federation.impl.FabricComponent - This node does not join a fabric: x
                """);
        assertThat(FabricTrouble.in(log)).contains("Fabric w: node node1 cannot reach the broker: cannot connect to "
                + "the broker tcp://127.0.0.1:9: Connection refused; trying again every 1000 ms");

        Path quiet = Files.writeString(dir.resolve("quiet.log"), "04:01:02.003 INFO x - all well\n");
        assertThat(FabricTrouble.in(quiet)).isEmpty();
        assertThat(FabricTrouble.in(dir.resolve("none.log"))).isEmpty();
    }

    @Test
    void aBrokerThatDoesNotAnswerIsNamedWithWhatToDo() throws Exception {
        int port;
        try (ServerSocket s = new ServerSocket(0, 1, java.net.InetAddress.getLoopbackAddress())) {
            port = s.getLocalPort();
            BrokerReach.check("tcp://127.0.0.1:" + port); // something answers: no error
        }
        String uri = "tcp://127.0.0.1:" + port; // closed now
        assertThatThrownBy(() -> BrokerReach.check(uri)).hasMessageStartingWith("--broker " + uri
                + ": nothing answers at 127.0.0.1:" + port + " (").hasMessageEndingWith("start the broker there, or "
                + "leave --broker out for the embedded one");
    }
}
