package eu.brain.iot.benchmarks.fabric;

import com.hivemq.client.mqtt.datatypes.MqttQos;
import com.hivemq.client.mqtt.mqtt5.Mqtt5AsyncClient;
import com.hivemq.client.mqtt.mqtt5.Mqtt5Client;
import java.nio.ByteBuffer;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

/**
 * The subscribing bare client, in a JVM of its own: {@code SubscriberMain URI TOPIC CLIENT_ID COUNT WARMUP
 * TIMEOUT_S}. Subscribes with QoS 1 and a persistent session (as a fabric node does), prints {@code ready}, then
 * counts COUNT messages and prints one {@code result} line: the receive time of message WARMUP (the first measured)
 * and of the last, the latency percentiles of the messages after the warm-up, duplicates and messages out of order.
 *
 * <p>Threads: the HiveMQ client's single callback thread receives every message and alone writes the counters and
 * the samples; the main thread reads them after the latch (which orders the writes before the reads).
 */
public final class SubscriberMain {
    private static final long SESSION_EXPIRY_S = 300;

    private SubscriberMain() {
    }

    public static void main(String[] args) throws Exception {
        BrokerAddress broker = BrokerAddress.parse(args[0]);
        String topic = args[1];
        int count = Integer.parseInt(args[3]);
        int warmup = Integer.parseInt(args[4]);
        long timeoutS = Long.parseLong(args[5]);
        long[] latencies = new long[count];
        long[] state = new long[5]; // received, next expected, first measured ns, last ns, out of order
        long[] duplicates = new long[1];
        boolean[] seen = new boolean[count];
        CountDownLatch done = new CountDownLatch(1);
        Mqtt5AsyncClient client = Mqtt5Client.builder().identifier(args[2]).serverHost(broker.host())
                .serverPort(broker.port()).buildAsync();
        client.connectWith().cleanStart(true).sessionExpiryInterval(SESSION_EXPIRY_S).send().get(30, TimeUnit.SECONDS);
        client.subscribeWith().topicFilter(topic).qos(MqttQos.AT_LEAST_ONCE).callback(p -> {
            long now = System.nanoTime();
            ByteBuffer payload = p.getPayload().orElseThrow();
            int seq = (int) Payload.sequence(payload);
            if (seq < 0 || seq >= count || seen[seq]) {
                duplicates[0]++;
                return;
            }
            seen[seq] = true;
            if (seq != state[1]) {
                state[4]++;
            }
            state[1] = seq + 1L;
            if (seq == warmup) {
                state[2] = now;
            }
            if (seq >= warmup) {
                latencies[seq - warmup] = now - Payload.sentNanos(payload);
            }
            state[3] = now;
            if (++state[0] == count) {
                done.countDown();
            }
        }).send().get(30, TimeUnit.SECONDS);
        System.out.println("ready");
        System.out.flush();
        boolean all = done.await(timeoutS, TimeUnit.SECONDS);
        client.disconnectWith().sessionExpiryInterval(0).send().get(30, TimeUnit.SECONDS);
        { // after the latch the callback thread's writes are visible; after a time-out the line says complete=false
            int measured = (int) Math.max(0, Math.min(count - warmup, state[0] - warmup));
            LatencyStats stats = LatencyStats.of(latencies, measured);
            System.out.println("result received=" + state[0] + " complete=" + all + " firstMeasuredNs=" + state[2]
                    + " lastNs=" + state[3] + " p50Ns=" + stats.p50Nanos() + " p99Ns=" + stats.p99Nanos() + " maxNs="
                    + stats.maxNanos() + " duplicates=" + duplicates[0] + " outOfOrder=" + state[4]);
        }
        System.out.flush();
        System.exit(0);
    }
}
