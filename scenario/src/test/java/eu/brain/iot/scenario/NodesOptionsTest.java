package eu.brain.iot.scenario;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import eu.brain.iot.federation.impl.FabricKey;

/** {@code --nodes} and {@code --kill-node}: good values, bad ones, node names checked against N. */
class NodesOptionsTest {

    @Test
    void oneNodeAloneByDefault() throws Exception {
        Options o = OptionsParser.parse();
        assertThat(o.nodes()).isEqualTo(1);
        assertThat(o.fabric()).as("one node alone joins no fabric").isNull();
    }

    @Test
    void severalNodesJoinAFabricOfTheRunsOwnThroughTheEmbeddedBroker() throws Exception {
        Options o = OptionsParser.parse("--nodes", "3");
        assertThat(o.nodes()).isEqualTo(3);
        assertThat(o.fabric().broker()).as("the run starts the embedded broker").isNull();
        assertThat(o.fabric().key()).as("a new key in the run's folder").isNull();
        assertThat(o.fabric().name()).matches("warehouse-[0-9a-f]{8}");
        assertThat(OptionsParser.parse("--nodes", "2").fabric().name()).as("unique per run")
                .isNotEqualTo(o.fabric().name());
    }

    @Test
    void severalNodesJoinAGivenBrokerWithAGivenKey(@TempDir Path dir) throws Exception {
        Path key = dir.resolve("fabric.key");
        FabricKey.generate(key);
        Options o = OptionsParser.parse("--nodes", "20", "--broker", "tcp://127.0.0.1:18830", "--fabric-key",
                key.toString());
        assertThat(o.fabric().broker()).isEqualTo("tcp://127.0.0.1:18830");
        assertThat(o.fabric().key()).isEqualTo(key);
        assertThat(o.fabric().name()).startsWith("warehouse-");
        assertThat(OptionsParser.parse("--nodes", "2", "--fabric-key", key.toString()).fabric().key())
                .as("a key without --broker, for the embedded broker").isEqualTo(key);
        assertThat(OptionsParser.parse("--broker", "tcp://127.0.0.1:18830").fabric().name())
                .as("one node keeps its fabric's name").isEqualTo("warehouse");
    }

    @Test
    void aRunThatKillsANodeIsTwiceAsFastAsRealTimeUnlessTold() throws Exception {
        assertThat(OptionsParser.parse("--nodes", "2", "--kill-node", "node2@20s").speed())
                .as("a lease lapsing (2.5 s of wall time) is 5 s of warehouse time").isEqualTo(2);
        assertThat(OptionsParser.parse("--nodes", "2", "--kill-node", "node2@20s", "--speed", "4").speed())
                .isEqualTo(4);
        assertThat(OptionsParser.parse("--nodes", "2").speed()).isEqualTo(OptionsParser.DEFAULT_SPEED);
    }

    @Test
    void nodesIsOneToTwenty() {
        for (String bad : new String[] {"0", "21", "-1", "two", "1.5"}) {
            assertThatThrownBy(() -> OptionsParser.parse("--nodes", bad))
                    .hasMessage("--nodes must be a whole number 1..20, found '" + bad + "'");
        }
        assertThatThrownBy(() -> OptionsParser.parse("--nodes")).hasMessage("--nodes needs a value: N, a fabric of N nodes, node1..nodeN, each its own JVM owning its share"
                + " of the fleet");
    }

    @Test
    void killNodeIsReadWithItsWarehouseTime() throws Exception {
        Options o = OptionsParser.parse("--nodes", "3", "--kill-node", "node2@20s", "--kill-node", "node3@1.5min");
        assertThat(o.faults()).containsExactly(new PlannedFault.KillNode("node2", 20_000, -1),
                new PlannedFault.KillNode("node3", 90_000, -1));
        assertThat(o.faults().get(0).describe()).isEqualTo("node2 killed (kill -9) at 20.0 s");
        assertThat(o.faults().get(0).endsAtMillis()).as("nothing to end").isEqualTo(20_000);
    }

    @Test
    void killNodeWithADowntimeStartsItAgainThatLongAfter() throws Exception {
        Options o = OptionsParser.parse("--nodes", "2", "--kill-node", "node2@20s+30s");
        PlannedFault f = o.faults().get(0);
        assertThat(f).isEqualTo(new PlannedFault.KillNode("node2", 20_000, 30_000));
        assertThat(f.describe()).isEqualTo("node2 killed (kill -9) at 20.0 s and started again 30.0 s later");
        assertThat(f.endsAtMillis()).as("started again then").isEqualTo(50_000);
        assertThat(f.endsWithTheRun()).as("not started after the run: reported as not done").isFalse();
        assertThatThrownBy(() -> OptionsParser.parse("--nodes", "2", "--kill-node", "node2@20s+0s"))
                .hasMessage("--kill-node 'node2@20s+0s': the DOWNTIME must be above 0");
        assertThatThrownBy(() -> OptionsParser.parse("--nodes", "2", "--kill-node", "node2@20s+later"))
                .hasMessageStartingWith("--kill-node 'node2@20s+later': the DOWNTIME 'later' is not a duration");
    }

    @Test
    void killNodeNamesOneOfTheRunsNodes() {
        assertThatThrownBy(() -> OptionsParser.parse("--nodes", "3", "--kill-node", "node4@20s"))
                .hasMessage("--kill-node: no node 'node4'; the run's nodes are node1..node3 (--nodes 3)");
        assertThatThrownBy(() -> OptionsParser.parse("--nodes", "2", "--kill-node", "robot1@20s"))
                .hasMessage("--kill-node: no node 'robot1'; the run's nodes are node1, node2 (--nodes 2)");
        assertThatThrownBy(() -> OptionsParser.parse("--nodes", "2", "--kill-node", "node0@20s"))
                .hasMessageContaining("no node 'node0'");
    }

    @Test
    void killingTheOnlyNodeIsRefused() {
        assertThatThrownBy(() -> OptionsParser.parse("--kill-node", "node1@20s"))
                .hasMessage("--kill-node node1: the run has one node, and killing the only node would end the run: "
                        + "give --nodes 2 or more");
        assertThatThrownBy(() -> OptionsParser.parse("--nodes", "1", "--kill-node", "node1@20s"))
                .hasMessageContaining("killing the only node");
    }

    @Test
    void killsThatWouldEndTheRunOrFindTheirNodeDownAreRefused() throws Exception {
        assertThatThrownBy(() -> OptionsParser.parse("--nodes", "2", "--kill-node", "node1@10s", "--kill-node",
                "node2@10s")).hasMessage("--kill-node: at 10.0 s every node of the run is down, which ends it: "
                        + "keep one running (or give a kill a downtime, +D, that brings its node back before)");
        assertThatThrownBy(() -> OptionsParser.parse("--nodes", "2", "--kill-node", "node1@10s+20s", "--kill-node",
                "node2@25s")).hasMessageStartingWith("--kill-node: at 25.0 s every node of the run is down");
        assertThatThrownBy(() -> OptionsParser.parse("--nodes", "3", "--kill-node", "node2@30s", "--kill-node",
                "node2@40s")).hasMessage("--kill-node node2 at 40.0 s: node2 is down then (killed at 30.0 s, for "
                        + "good): kill it once it is back, or give the earlier kill a shorter downtime");
        assertThatThrownBy(() -> OptionsParser.parse("--nodes", "3", "--kill-node", "node2@30s+20s", "--kill-node",
                "node2@40s")).hasMessageContaining("(killed at 30.0 s, started again at 50.0 s)");

        assertThat(OptionsParser.parse("--nodes", "2", "--kill-node", "node1@10s+5s", "--kill-node", "node2@20s")
                .faults()).hasSize(2); // node1 is back at 15 s
        assertThat(OptionsParser.parse("--nodes", "3", "--kill-node", "node2@10s+5s", "--kill-node", "node2@20s")
                .faults()).hasSize(2); // killed again once back
    }

    @Test
    void aKillNodeMistakeNamesThePartThatIsWrong() {
        assertThatThrownBy(() -> OptionsParser.parse("--nodes", "2", "--kill-node", "node2"))
                .hasMessage("--kill-node 'node2': write NODE@TIME or NODE@TIME+DOWNTIME, e.g. node2@20s (node2 killed "
                        + "with kill -9 20 s of warehouse time into the scenario) or node2@20s+30s (and started again "
                        + "30 s later); the @TIME is missing");
        assertThatThrownBy(() -> OptionsParser.parse("--nodes", "2", "--kill-node", "@20s"))
                .hasMessageEndingWith("the NODE before '@' is missing");
        assertThatThrownBy(() -> OptionsParser.parse("--nodes", "2", "--kill-node", "node2@soon"))
                .hasMessageStartingWith("--kill-node 'node2@soon': the TIME 'soon' is not a duration");
    }

    @Test
    void aBadKillNodeExitsWith2AndOneLine(@TempDir Path dir) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int code = Main.run(new String[] {"--nodes", "2", "--kill-node", "node5@20s", "--run-dir", dir.toString()},
                new PrintStream(out), new PrintStream(err));
        assertThat(code).isEqualTo(2);
        assertThat(err.toString(StandardCharsets.UTF_8)).startsWith("warehouse-scenario: --kill-node: no node "
                + "'node5'; the run's nodes are node1, node2 (--nodes 2)\n"
                + "(./warehouse-scenario --help lists the options)\n");
        assertThat(dir).as("nothing started").isEmptyDirectory();
        assertThat(Files.exists(dir.resolve("node1"))).isFalse();
    }
}
