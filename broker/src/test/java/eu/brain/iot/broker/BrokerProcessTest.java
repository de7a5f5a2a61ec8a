package eu.brain.iot.broker;

import static org.assertj.core.api.Assertions.assertThat;

import com.hivemq.client.mqtt.MqttGlobalPublishFilter;
import com.hivemq.client.mqtt.datatypes.MqttQos;
import com.hivemq.client.mqtt.mqtt5.Mqtt5BlockingClient;
import com.hivemq.client.mqtt.mqtt5.Mqtt5Client;
import com.hivemq.client.mqtt.mqtt5.message.publish.Mqtt5Publish;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The launcher as a user runs it: {@code java -jar target/broker.jar}, reached by a real MQTT 5 client. */
class BrokerProcessTest {
    private static final int MESSAGES = 200;
    private static final String TOPIC = "fabric/test/events";
    /** Seconds the broker keeps the subscriber's session while it is offline. */
    private static final long SESSION_EXPIRY_S = 600;

    @TempDir
    Path data;

    @Test
    void queuedQos1MessagesForAnOfflinePersistentSessionSurviveARestart() throws Exception {
        int port = BrokerProcess.freePort();
        String[] args = {"--port", String.valueOf(port), "--data", data.toString()};
        try (BrokerProcess broker = BrokerProcess.started(args)) {
            assertThat(broker.awaitLine(BrokerMain.READY_PREFIX))
                    .startsWith("broker listening on 127.0.0.1:" + port + " (tcp://127.0.0.1:" + port)
                    .contains("persistence file");
            Mqtt5BlockingClient subscriber = client("subscriber", port);
            subscriber.connectWith().cleanStart(true).sessionExpiryInterval(SESSION_EXPIRY_S).send();
            subscriber.subscribeWith().topicFilter(TOPIC).qos(MqttQos.AT_LEAST_ONCE).send();
            subscriber.disconnect();

            Mqtt5BlockingClient publisher = client("publisher", port);
            publisher.connect();
            for (int i = 0; i < MESSAGES; i++) {
                publisher.publishWith().topic(TOPIC).qos(MqttQos.AT_LEAST_ONCE)
                        .payload(String.valueOf(i).getBytes(StandardCharsets.UTF_8)).send();
            }
            publisher.disconnect();
        }
        try (BrokerProcess broker = BrokerProcess.started(args)) {
            Mqtt5BlockingClient subscriber = client("subscriber", port);
            try (Mqtt5BlockingClient.Mqtt5Publishes publishes = subscriber.publishes(MqttGlobalPublishFilter.ALL)) {
                assertThat(subscriber.connectWith().cleanStart(false).sessionExpiryInterval(SESSION_EXPIRY_S).send()
                        .isSessionPresent()).as("the session kept across the restart").isTrue();
                List<Integer> received = new ArrayList<>();
                while (received.size() < MESSAGES) {
                    Optional<Mqtt5Publish> p = publishes.receive(30, TimeUnit.SECONDS);
                    assertThat(p).as("message %d of %d after the restart", received.size() + 1, MESSAGES).isPresent();
                    received.add(Integer.valueOf(new String(p.get().getPayloadAsBytes(), StandardCharsets.UTF_8)));
                }
                assertThat(received).as("every message, in publish order")
                        .containsExactlyElementsOf(java.util.stream.IntStream.range(0, MESSAGES).boxed().toList());
            }
            subscriber.disconnectWith().sessionExpiryInterval(0).send();
        }
    }

    @Test
    void aTakenPortIsReportedWithWhatToDo() throws Exception {
        int port = BrokerProcess.freePort();
        try (BrokerProcess first = BrokerProcess.started("--port", String.valueOf(port), "--in-memory",
                "--data", data.resolve("a").toString());
             BrokerProcess second = BrokerProcess.start("--port", String.valueOf(port), "--in-memory",
                "--data", data.resolve("b").toString())) {
            assertThat(second.awaitExit()).isEqualTo(1);
            assertThat(second.lines()).anySatisfy(l -> assertThat(l)
                    .startsWith("broker: cannot listen on 127.0.0.1:" + port)
                    .endsWith("Choose another port with --port N"));
            assertThat(second.lines()).noneMatch(l -> l.contains("\tat "));
        }
    }

    @Test
    void aBadCommandLineExitsWith2AndTheUsage() throws Exception {
        try (BrokerProcess broker = BrokerProcess.start("--port", "zero")) {
            assertThat(broker.awaitExit()).isEqualTo(2);
            assertThat(broker.lines()).first().isEqualTo("broker: --port needs a whole number 1..65535, found 'zero'");
            assertThat(broker.lines()).anyMatch(l -> l.startsWith("Usage: java -jar broker.jar"));
        }
    }

    private static Mqtt5BlockingClient client(String id, int port) {
        return Mqtt5Client.builder().identifier(id).serverHost("127.0.0.1").serverPort(port).buildBlocking();
    }
}
