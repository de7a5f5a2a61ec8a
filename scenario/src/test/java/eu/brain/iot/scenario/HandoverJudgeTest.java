package eu.brain.iot.scenario;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.ObjectMapper;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import org.junit.jupiter.api.Test;

/**
 * The judge's check that one node at a time commands each robot: on robot-sim's record of the {@code X-Brain-Node}
 * header (real HTTP), and on hand-made ground truth for exact times.
 */
class HandoverJudgeTest {
    private static final ObjectMapper JSON = new ObjectMapper();
    private static final String CHECK = "one node commanding each robot at a time";
    private final HttpClient http = HttpClient.newHttpClient();

    private int goTo(Fleet f, String robot, String node, int x, int y) throws Exception {
        return http.send(HttpRequest.newBuilder(f.base().resolve(robot
                        + "/robot_local_control/NavigationComponent/GoToComponent/add"))
                .header("Content-Type", "application/json").header("X-Brain-Node", node)
                .POST(HttpRequest.BodyPublishers.ofString("{\"x\":" + x + ",\"y\":" + y + "}")).build(),
                HttpResponse.BodyHandlers.ofString()).statusCode();
    }

    private static Verdict.Check check(Verdict v) {
        return v.checks().stream().filter(c -> c.name().startsWith(CHECK)).findFirst().orElseThrow();
    }

    @Test
    void aRunOnOneNodePasses() throws Exception {
        try (Fleet f = Fleet.paper()) {
            assertThat(goTo(f, "robot1", "node", 2, 4)).isEqualTo(200);
            assertThat(goTo(f, "robot2", "node", 4, 4)).isEqualTo(200);
            assertThat(goTo(f, "robot1", "node", 2, 3)).isEqualTo(200);
            Verdict.Check c = check(Judge.judge(f.world(), 10_000, -1));
            assertThat(c.passed()).isTrue();
            assertThat(c.name()).contains("2.0 s of wall time");
            assertThat(c.detail()).isEqualTo("2 robot(s), all commanded by node node");
        }
    }

    @Test
    void twoNodesCommandingOneRobotWithinTheLeaseFailNamingTheRobotTheNodesAndTheTimes() throws Exception {
        try (Fleet f = Fleet.paper()) {
            assertThat(goTo(f, "robot3", "node1", 6, 3)).isEqualTo(200);
            f.step(4);
            assertThat(goTo(f, "robot3", "node2", 6, 4)).isEqualTo(200);
            assertThat(goTo(f, "robot1", "node1", 2, 4)).isEqualTo(200);
            Verdict v = Judge.judge(f.world(), 10_000, -1);
            assertThat(v.passed()).isFalse();
            Verdict.Check c = check(v);
            assertThat(c.passed()).isFalse();
            assertThat(c.detail()).startsWith("1 robot command(s) from a second node within the lease: robot3 by "
                    + "node1 at 0.0 s then by node2 at 2.0 s of warehouse time (")
                    .endsWith(" of wall time apart)").doesNotContain("robot1");
            assertThat(Judge.oneCommanderAtATime(f.world(), 0).passed()).as("no lease: any hand-over is fine")
                    .isTrue();
        }
    }

    @Test
    void robotsSplitOverNodesWithoutHandOverPassNamingTheNodes() throws Exception {
        try (Fleet f = Fleet.paper()) {
            assertThat(goTo(f, "robot1", "node1", 2, 4)).isEqualTo(200);
            assertThat(goTo(f, "robot2", "node2", 4, 4)).isEqualTo(200);
            Verdict.Check c = check(Judge.judge(f.world(), 10_000, -1));
            assertThat(c.passed()).isTrue();
            assertThat(c.detail()).isEqualTo("2 robot(s), each commanded by one node only (nodes node1, node2)");
        }
    }

    @Test
    void noCommandAtAllIsNoFailureOfThisCheck() throws Exception {
        try (Fleet f = Fleet.paper()) {
            assertThat(check(Judge.judge(f.world(), 10_000, -1)).detail()).isEqualTo("no robot took a command");
        }
    }

    /** Ground truth as robot-sim writes it: node1 died, node2 took robot1 over 2.5 s later, robot2 0.8 s later. */
    private static WorldSnapshot handedOver(long robot2GapMs, boolean logDroppedRobot2) throws Exception {
        String robot2Change = "{\"robot\":\"robot2\",\"from\":\"node1\",\"to\":\"node3\",\"fromLastWarehouseMs\":"
                + "40000,\"fromLastWallMillis\":1000000,\"warehouseMs\":41000,\"wallMillis\":" + (1_000_000
                + robot2GapMs) + "}";
        String robot1Change = "{\"robot\":\"robot1\",\"from\":\"node1\",\"to\":\"node2\",\"fromLastWarehouseMs\":"
                + "40000,\"fromLastWallMillis\":1000000,\"warehouseMs\":45000,\"wallMillis\":1002500}";
        String doc = "{\"commandOrigins\":{\"robots\":{"
                + "\"robot1\":{\"node\":\"node2\",\"handovers\":1,\"closestHandover\":" + robot1Change + "},"
                + "\"robot2\":{\"node\":\"node3\",\"handovers\":1,\"closestHandover\":" + robot2Change + "},"
                + "\"robot3\":{\"node\":\"node2\",\"handovers\":0,\"closestHandover\":null}},"
                + "\"changes\":[" + robot1Change + (logDroppedRobot2 ? "" : "," + robot2Change) + "],"
                + "\"changesKept\":1,\"changesDropped\":" + (logDroppedRobot2 ? 1 : 0) + "}}";
        return new WorldSnapshot(JSON.readTree(doc));
    }

    @Test
    void handOversAfterTheLeasePass() throws Exception {
        Verdict.Check c = Judge.oneCommanderAtATime(handedOver(2_000, false), 2_000);
        assertThat(c.passed()).isTrue();
        assertThat(c.detail()).isEqualTo("3 robot(s) commanded by node1, node2, node3; 2 hand-over(s), the closest "
                + "2.0 s of wall time apart");
    }

    @Test
    void aHandOverInsideTheLeaseFailsEvenWhenTheBoundedLogDroppedIt() throws Exception {
        for (boolean dropped : new boolean[] {false, true}) {
            Verdict.Check c = Judge.oneCommanderAtATime(handedOver(800, dropped), 2_000);
            assertThat(c.passed()).as("log dropped it: " + dropped).isFalse();
            assertThat(c.detail()).as("log dropped it: " + dropped).startsWith("1 robot command(s) from a second "
                    + "node within the lease: robot2 by node1 at 40.0 s then by node3 at 41.0 s of warehouse time")
                    .endsWith("0.8 s of wall time apart)");
        }
        assertThat(Judge.oneCommanderAtATime(handedOver(800, false), 500).passed())
                .as("a shorter lease period: 0.8 s is outside it").isTrue();
    }
}
