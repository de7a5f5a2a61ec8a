package eu.brain.iot.federation.impl;

import java.util.List;

import org.eclipse.paho.mqttv5.client.MqttAsyncClient;
import org.eclipse.paho.mqttv5.client.MqttConnectionOptions;
import org.eclipse.paho.mqttv5.client.persist.MemoryPersistence;
import org.eclipse.paho.mqttv5.common.MqttException;
import org.eclipse.paho.mqttv5.common.MqttMessage;
import org.eclipse.paho.mqttv5.common.packet.MqttProperties;
import org.eclipse.paho.mqttv5.common.packet.UserProperty;

/**
 * A client of the fabric's broker that is no member of the fabric: it publishes what it likes on the fabric's topics,
 * with a signature of its own choosing (none, one made with another key, or a replayed one).
 * <p>
 * Threads: the test's.
 */
final class Intruder implements AutoCloseable {

    private static final long WAIT_MILLIS = 15_000;
    private final MqttAsyncClient client;

    /** Connects to the broker. */
    Intruder(String brokerUri) throws MqttException {
        client = new MqttAsyncClient(brokerUri, "intruder", new MemoryPersistence());
        client.connect(new MqttConnectionOptions()).waitForCompletion(WAIT_MILLIS);
    }

    /** Publishes with QoS 1 and waits until the broker took it; {@code signature} null: unsigned. */
    void publish(String topic, byte[] payload, String signature, boolean retained) throws MqttException {
        MqttProperties props = new MqttProperties();
        if (signature != null) {
            props.setUserProperties(List.of(new UserProperty(MqttLink.SIG, signature)));
        }
        client.publish(topic, new MqttMessage(payload, 1, retained, props)).waitForCompletion(WAIT_MILLIS);
    }

    @Override
    public void close() throws MqttException {
        client.disconnectForcibly(0, 1, false);
        client.close(true);
    }
}
