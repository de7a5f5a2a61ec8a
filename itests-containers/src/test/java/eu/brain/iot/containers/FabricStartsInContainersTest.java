package eu.brain.iot.containers;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import com.hivemq.client.mqtt.MqttGlobalPublishFilter;
import com.hivemq.client.mqtt.datatypes.MqttQos;
import com.hivemq.client.mqtt.mqtt5.Mqtt5BlockingClient;
import com.hivemq.client.mqtt.mqtt5.Mqtt5Client;
import com.hivemq.client.mqtt.mqtt5.message.publish.Mqtt5Publish;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.testcontainers.containers.GenericContainer;

/**
 * The broker, robot-sim and two fabric nodes, each in its own container on a network of their own, start from the
 * images this module builds: the nodes are ready and their REST APIs answer (node A lists the robots it polls in
 * the robot-sim container), and the broker carries MQTT 5 messages.
 */
class FabricStartsInContainersTest {
    private static FabricContainers fabric;
    private static GenericContainer<?> broker;
    private static NodeContainer nodeA;
    private static NodeContainer nodeB;

    @BeforeAll
    static void start() {
        DockerEngine.assumeAvailable();
        fabric = new FabricContainers(TestSettings.fromSystemProperties());
        broker = fabric.broker();
        fabric.robotSim();
        nodeA = fabric.node("nodeA", true, Map.of());
        nodeB = fabric.node("nodeB", false, Map.of());
    }

    @AfterAll
    static void stop() {
        if (fabric != null) {
            fabric.close();
        }
    }

    @Test
    void nodesAreReadyAndTheirRestApisAnswerWithTheToken() throws Exception {
        for (NodeContainer node : new NodeContainer[] {nodeA, nodeB}) {
            assertThat(node.logs()).contains(FabricContainers.NODE_READY).doesNotContain("WITH PROBLEMS");
            await(node.name() + "'s REST API").atMost(Duration.ofSeconds(60)).pollInterval(Duration.ofMillis(250))
                    .ignoreExceptions().until(() -> node.get("/sensinact/providers", true).status() == 200);
            PlainHttp.Answer refused = node.get("/sensinact/providers", false);
            assertThat(refused.status()).as("without the token").isEqualTo(401);
            assertThat(refused.body()).startsWith("{");
        }
        await("node A lists the robots of the robot-sim container").atMost(Duration.ofSeconds(60))
                .pollInterval(Duration.ofMillis(250))
                .until(() -> nodeA.get("/sensinact/providers", true).body(), body -> body.contains("\"robot1\""));
        assertThat(nodeB.get("/sensinact/providers", true).body()).doesNotContain("\"robot1\"");
    }

    @Test
    void theBrokerCarriesMqtt5Messages() throws Exception {
        String host = broker.getHost();
        int port = broker.getMappedPort(FabricContainers.MQTT_PORT);
        Mqtt5BlockingClient subscriber = Mqtt5Client.builder().identifier("itest-sub").serverHost(host)
                .serverPort(port).buildBlocking();
        Mqtt5BlockingClient publisher = Mqtt5Client.builder().identifier("itest-pub").serverHost(host)
                .serverPort(port).buildBlocking();
        try (Mqtt5BlockingClient.Mqtt5Publishes publishes = subscriber.publishes(MqttGlobalPublishFilter.ALL)) {
            subscriber.connect();
            subscriber.subscribeWith().topicFilter("itest/hello").qos(MqttQos.AT_LEAST_ONCE).send();
            publisher.connect();
            publisher.publishWith().topic("itest/hello").qos(MqttQos.AT_LEAST_ONCE)
                    .payload("from the host".getBytes(StandardCharsets.UTF_8)).send();
            Optional<Mqtt5Publish> received = publishes.receive(20, TimeUnit.SECONDS);
            assertThat(received).isPresent();
            assertThat(new String(received.get().getPayloadAsBytes(), StandardCharsets.UTF_8)).isEqualTo("from the host");
        } finally {
            publisher.disconnect();
            subscriber.disconnect();
        }
    }
}
