package eu.brain.iot.containers;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.github.dockerjava.api.DockerClient;
import eu.brain.iot.scenario.Judge;
import eu.brain.iot.scenario.Verdict;
import eu.brain.iot.scenario.WorldSnapshot;
import java.io.IOException;
import java.time.Duration;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;
import org.awaitility.core.ConditionTimeoutException;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.testcontainers.DockerClientFactory;
import org.testcontainers.containers.GenericContainer;

/**
 * The paper's warehouse on a fabric of two nodes, each in a container of its own beside the broker's and
 * robot-sim's: node1 polls robot2 and the door, node2 robot1 and robot3 (the edge's leased share, robot number modulo
 * 2), the behaviours are installed on demand and cooperate through the broker. Once node2 commands a robot that is on
 * an errand, node2's container is killed (SIGKILL, as {@code kill -9}); node1 takes node2's robots when their lease
 * lapses and finishes the warehouse. The run is judged by the scenario's judge on robot-sim's ground truth: every
 * cart in storage, every robot docked, no wait over 10 s, no deadlock, no robot commanded by two nodes within a
 * lease period.
 *
 * <p>Speed 2, as the scenario's kill examples: REQ-2's 10 s limit is 5 s of wall time, a lease (2 s of wall time) 4 s
 * of warehouse time.
 */
class WarehouseAcrossContainersTest {
    private static final double SPEED = 2;
    private static final long WAIT_LIMIT_MS = 10_000;
    /** robot-sim's step, warehouse ms. */
    private static final long STEP_MS = 500;
    private static final long LEASE_MS = Judge.DEFAULT_LEASE_MS;
    private static final long RENEW_MS = 500;
    private static final String NODE1 = "node1";
    private static final String NODE2 = "node2";
    /** The robots of node2's share (robot number modulo 2). */
    private static final List<String> NODE2_ROBOTS = List.of("robot1", "robot3");
    private static final Duration FIRST_ERRAND_TIMEOUT = Duration.ofMinutes(3);
    private static final Duration FINISH_TIMEOUT = Duration.ofMinutes(3);
    private static final ObjectMapper JSON = new ObjectMapper();

    private static FabricContainers fabric;
    private static GenericContainer<?> robotSim;
    private static NodeContainer node1;
    private static NodeContainer node2;

    @BeforeAll
    static void start() {
        DockerEngine.assumeAvailable();
        FederatedProbes key = new FederatedProbes();
        fabric = new FabricContainers(TestSettings.fromSystemProperties());
        fabric.broker();
        robotSim = fabric.robotSim("--seed", "3", "--speed", String.valueOf(SPEED), "--deadlock-steps",
                String.valueOf(WAIT_LIMIT_MS / STEP_MS));
        Map<String, Map<String, String>> configs = new LinkedHashMap<>();
        configs.put(NODE1, configFiles(key, NODE1, 1));
        configs.put(NODE2, configFiles(key, NODE2, 2));
        List<NodeContainer> nodes = fabric.nodesTogether(configs, key.keyFile());
        node1 = nodes.get(0);
        node2 = nodes.get(1);
    }

    @AfterAll
    static void stop() {
        if (fabric != null) {
            fabric.close();
        }
    }

    @Test
    void aNodeKilledMidErrandHandsItsRobotsToTheOtherNodeAndTheWarehouseCompletes() {
        String onErrand = awaitOrFail("node2 commanding a robot on an errand", FIRST_ERRAND_TIMEOUT,
                () -> node2RobotOnErrand(world()));
        DockerClient docker = DockerClientFactory.instance().client();
        String id = node2.container().getContainerId();
        docker.killContainerCmd(id).exec(); // SIGKILL to the node's JVM, as kill -9
        await("node2's container down").atMost(Duration.ofSeconds(30))
                .until(() -> !Boolean.TRUE.equals(docker.inspectContainerCmd(id).exec().getState().getRunning()));

        WorldSnapshot end = awaitOrFail("the warehouse done", FINISH_TIMEOUT, () -> {
            WorldSnapshot w = world();
            return w.finished() ? w : null;
        });
        Verdict verdict = Judge.judge(end, WAIT_LIMIT_MS, Judge.RunEnd.FINISHED, end.warehouseMillis(), LEASE_MS);
        verdict.checks().forEach(c -> System.out.println("warehouse in containers: "
                + (c.passed() ? "PASS  " : "FAIL  ") + c.name() + ": " + c.detail()));
        assertThat(verdict.failed()).as(() -> diagnosis("failed checks: " + verdict.failed())).isEmpty();
        assertThat(end.lastCommanders()).as(() -> diagnosis("the last commander of each robot ("
                + onErrand + " was on an errand when node2 was killed)"))
                .containsEntry("robot1", NODE1).containsEntry("robot2", NODE1).containsEntry("robot3", NODE1);
        assertThat(end.handovers()).as(() -> diagnosis("hand-overs from node2 to node1"))
                .anyMatch(h -> h.from().equals(NODE2) && h.to().equals(NODE1) && h.robot().equals(onErrand));
        assertThat(node1.logs()).as("node1 took node2's robots")
                .containsPattern("Device leases of node node1: took \\[.*robot(1|3)");
    }

    /**
     * The configuration folder of node {@code number} of 2: the fabric's membership, the device leases, the edge
     * polling its share of robot-sim's fleet (the door on node1) every 0.5 s of warehouse time, the behaviours' speed
     * and the traffic planner (as the scenario runner writes them).
     */
    private static Map<String, String> configFiles(FederatedProbes key, String name, int number) {
        Map<String, String> files = new LinkedHashMap<>(key.configFiles(name, false));
        files.put("eu.brain.iot.federation.lease.cfg", cfg(Map.of("lease.ms", LEASE_MS, "renew.ms", RENEW_MS)));
        files.put("eu.brain.iot.edge.cfg", cfg(Map.of(
                "fleet.url", "http://" + FabricContainers.ROBOT_SIM + ":" + FabricContainers.FLEET_PORT + "/",
                "share", number + "/2", "share.leased", true, "doors.owner", 1,
                "poll.period.ms", Math.round(STEP_MS / SPEED), "backoff.max.ms", Math.round(8_000 / SPEED),
                "world.period.ms", Math.round(2_000 / SPEED))));
        files.put("eu.brain.iot.behaviours.robot.cfg", cfg(Map.of("speed", SPEED, "traffic", true)));
        files.put("eu.brain.iot.behaviours.door.cfg", cfg(Map.of("speed", SPEED)));
        return files;
    }

    private static String cfg(Map<String, Object> properties) {
        return properties.entrySet().stream().map(e -> e.getKey() + "=" + e.getValue())
                .collect(Collectors.joining("\n", "", "\n"));
    }

    /** robot-sim's {@code GET /world}: the ground truth. */
    private static WorldSnapshot world() throws IOException {
        PlainHttp.Answer a = PlainHttp.get(robotSim.getHost(), robotSim.getMappedPort(FabricContainers.FLEET_PORT),
                FabricContainers.ROBOT_SIM + ":" + FabricContainers.FLEET_PORT, "/world", null);
        if (a.status() != 200) {
            throw new IOException("robot-sim answered GET /world with " + a.status() + ": " + a.body());
        }
        return new WorldSnapshot(JSON.readTree(a.body()));
    }

    /** A robot of node2's share that node2 commanded last and that has a mission running, or null. */
    private static String node2RobotOnErrand(WorldSnapshot w) {
        Map<String, String> last = w.lastCommanders();
        for (JsonNode r : w.doc().path("robots")) {
            String robot = r.path("id").asText();
            if (NODE2_ROBOTS.contains(robot) && NODE2.equals(last.get(robot))
                    && r.path("mission").path("state").asText("").equals("running")) {
                return robot;
            }
        }
        return null;
    }

    private interface Probe<T> {
        T get() throws Exception;
    }

    /** Waits for {@code probe} to give a value; fails with both nodes' logs when it does not in time. */
    private static <T> T awaitOrFail(String what, Duration timeout, Probe<T> probe) {
        Object[] seen = new Object[1];
        try {
            await(what).atMost(timeout).pollInterval(Duration.ofMillis(200)).ignoreExceptions().until(() -> {
                seen[0] = probe.get();
                return seen[0] != null;
            });
        } catch (ConditionTimeoutException e) {
            throw new AssertionError(diagnosis(e.getMessage()), e);
        }
        @SuppressWarnings("unchecked")
        T value = (T) seen[0];
        return value;
    }

    private static String diagnosis(String what) {
        String world;
        try {
            WorldSnapshot w = world();
            world = "robot-sim at " + w.warehouseMillis() / 1000.0 + " s: " + w.doc().path("robots") + " carts "
                    + w.doc().path("carts") + " commands " + w.doc().path("commandOrigins");
        } catch (IOException e) {
            world = "robot-sim's world unreadable: " + e.getMessage();
        }
        return what + "\n" + world + "\n--- node1's log, its end:\n" + LogLineWait.tail(node1.logs(), 60)
                + "\n--- node2's:\n" + LogLineWait.tail(node2.logs(), 60);
    }
}
