package eu.brain.iot.containers;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import com.github.dockerjava.api.DockerClient;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.regex.Pattern;
import org.awaitility.core.ConditionTimeoutException;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.MethodOrderer;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestMethodOrder;
import org.testcontainers.DockerClientFactory;
import org.testcontainers.containers.GenericContainer;
import org.testcontainers.images.builder.Transferable;

/**
 * Two nodes joined through the broker, each in its own container: events published on node A (the probe
 * publisher) are counted inside the {@code notify()} of a behaviour on node B (the probe counter), none lost,
 * none twice, in order; node B killed and started again mid-stream misses nothing; the broker container restarted
 * mid-stream loses nothing.
 */
@TestMethodOrder(MethodOrderer.OrderAnnotation.class)
class EventsAcrossContainersTest {
    private static final int RATE = 500;
    private static final Duration DELIVERY_TIMEOUT = Duration.ofMinutes(2);

    private static FabricContainers fabric;
    private static GenericContainer<?> broker;
    private static NodeContainer nodeA;
    private static NodeContainer nodeB;

    @BeforeAll
    static void start() throws Exception {
        DockerEngine.assumeAvailable();
        TestSettings settings = TestSettings.fromSystemProperties();
        FederatedProbes probes = new FederatedProbes();
        fabric = new FabricContainers(settings);
        broker = fabric.broker();
        nodeB = fabric.node("nodeB", false, probes.configFiles("nodeB", true), probes.files());
        nodeA = fabric.node("nodeA", false, probes.configFiles("nodeA", false), probes.files());
        await("node B's probe counter").atMost(Duration.ofSeconds(60)).pollInterval(Duration.ofMillis(200))
                .until(() -> nodeB.logs().contains("probe counter: ready"));
    }

    @AfterAll
    static void stop() {
        if (fabric != null) {
            fabric.close();
        }
    }

    @Test
    @Order(1)
    void anEventPublishedOnNodeAIsCountedInsideABehaviourOnNodeB() {
        publish("basic", 1000);
        FederatedProbes.Counts c = awaitAll("basic", 1000);
        assertThat(c.duplicates()).as("duplicates").isZero();
        assertThat(c.outOfOrder()).as("out of order").isZero();
        assertThat(c.received()).isEqualTo(1000);
    }

    @Test
    @Order(2)
    void nodeBKilledAndStartedAgainMissesNothing() {
        long count = 8L * RATE;
        publish("killB", count);
        awaitReceivedAtLeast("killB", RATE);
        DockerClient docker = DockerClientFactory.instance().client();
        String id = nodeB.container().getContainerId();
        docker.killContainerCmd(id).exec(); // SIGKILL to the node's JVM, as kill -9
        await("node B's container down").atMost(Duration.ofSeconds(30))
                .until(() -> !Boolean.TRUE.equals(docker.inspectContainerCmd(id).exec().getState().getRunning()));
        docker.startContainerCmd(id).exec();
        await("node B ready again").atMost(Duration.ofMinutes(3)).pollInterval(Duration.ofMillis(500))
                .until(() -> occurrences(nodeB.logs(), FabricContainers.NODE_READY) >= 2);
        FederatedProbes.Counts c = awaitAll("killB", count);
        assertThat(c.duplicates()).as("duplicates: only an event caught inside notify() by the kill may come again")
                .isLessThanOrEqualTo(1);
        assertThat(c.outOfOrder()).as("out of order (a duplicate counts as one)").isLessThanOrEqualTo(c.duplicates());
    }

    @Test
    @Order(3)
    void theBrokerRestartedMidStreamLosesNothing() {
        long count = 8L * RATE;
        publish("brokerRestart", count);
        awaitReceivedAtLeast("brokerRestart", RATE);
        DockerClient docker = DockerClientFactory.instance().client();
        docker.restartContainerCmd(broker.getContainerId()).withTimeout(10).exec();
        FederatedProbes.Counts c = awaitAll("brokerRestart", count);
        assertThat(c.duplicates()).as("duplicates").isZero();
        assertThat(c.outOfOrder()).as("out of order").isZero();
    }

    private static void publish(String run, long count) {
        nodeA.container().copyFileToContainer(Transferable.of(FederatedProbes.publisherConfig(run, count, RATE)
                .getBytes(StandardCharsets.UTF_8), 0644), FabricContainers.CONFIG_DIR + FederatedProbes.publisherFile(run));
    }

    private static void awaitReceivedAtLeast(String run, long n) {
        await("node B counted " + n + " events of run " + run).atMost(DELIVERY_TIMEOUT)
                .pollInterval(Duration.ofMillis(200)).until(() -> FederatedProbes.lastCounts(nodeB.logs(), run)
                        .map(c -> c.received() >= n).orElse(false));
    }

    private static FederatedProbes.Counts awaitAll(String run, long count) {
        try {
            await("node B counted every event of run " + run).atMost(DELIVERY_TIMEOUT)
                    .pollInterval(Duration.ofMillis(250))
                    .until(() -> FederatedProbes.lastCounts(nodeB.logs(), run).map(c -> c.distinct() == count)
                            .orElse(false));
        } catch (ConditionTimeoutException e) {
            throw new AssertionError(e.getMessage() + "; node B counted "
                    + FederatedProbes.lastCounts(nodeB.logs(), run) + "\n--- node A's log, its end:\n"
                    + LogLineWait.tail(nodeA.logs(), 40) + "\n--- node B's:\n" + LogLineWait.tail(nodeB.logs(), 40),
                    e);
        }
        return FederatedProbes.lastCounts(nodeB.logs(), run).orElseThrow();
    }


    private static int occurrences(String text, String what) {
        return (int) Pattern.compile(Pattern.quote(what)).matcher(text).results().count();
    }
}
