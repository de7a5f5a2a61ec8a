package eu.brain.iot.benchmarks.fabric;

import com.hivemq.client.mqtt.datatypes.MqttQos;
import com.hivemq.client.mqtt.mqtt5.Mqtt5AsyncClient;
import com.hivemq.client.mqtt.mqtt5.Mqtt5Client;
import java.util.concurrent.Semaphore;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;

/**
 * The publishing bare client: QoS 1, at most {@link #WINDOW} messages handed to the client and not yet acknowledged
 * by the broker (the client itself keeps to the broker's receive maximum; the window bounds its queue).
 *
 * <p>Threads: the benchmark thread publishes; the client's threads release the window on each PUBACK.
 */
final class Publisher implements AutoCloseable {
    static final int WINDOW = 1000;
    private final Mqtt5AsyncClient client;
    private final String topic;
    private final Semaphore window = new Semaphore(WINDOW);

    Publisher(BrokerAddress broker, String topic, String clientId) throws Exception {
        this.topic = topic;
        this.client = Mqtt5Client.builder().identifier(clientId).serverHost(broker.host()).serverPort(broker.port())
                .buildAsync();
        client.connectWith().cleanStart(true).send().get(30, TimeUnit.SECONDS);
    }

    /** Messages {@code 0..count-1} back to back. Returns the nanoTime before the first. */
    long flood(int count) throws InterruptedException {
        long start = System.nanoTime();
        for (int i = 0; i < count; i++) {
            send(i);
        }
        return start;
    }

    /** Messages {@code 0..count-1} at {@code perSecond}, each at its slot (late ones go at once). */
    void paced(int count, int perSecond) throws InterruptedException {
        long interval = TimeUnit.SECONDS.toNanos(1) / perSecond;
        long next = System.nanoTime();
        for (int i = 0; i < count; i++) {
            long wait = next - System.nanoTime();
            if (wait > 0) {
                LockSupport.parkNanos(wait);
            }
            send(i);
            next += interval;
        }
    }

    private void send(int sequence) throws InterruptedException {
        window.acquire();
        client.publishWith().topic(topic).qos(MqttQos.AT_LEAST_ONCE)
                .payload(Payload.encode(sequence, System.nanoTime())).send()
                .whenComplete((ack, error) -> window.release());
    }

    /** Waits until the broker acknowledged every message. */
    void drain() throws InterruptedException {
        if (!window.tryAcquire(WINDOW, 60, TimeUnit.SECONDS)) {
            throw new IllegalStateException("the broker did not acknowledge the last messages within 60 s");
        }
        window.release(WINDOW);
    }

    @Override
    public void close() throws Exception {
        client.disconnect().get(30, TimeUnit.SECONDS);
    }
}
