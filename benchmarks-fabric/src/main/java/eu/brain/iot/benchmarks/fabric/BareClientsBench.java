package eu.brain.iot.benchmarks.fabric;

/**
 * Two bare MQTT 5 clients with QoS 1 through one broker, publisher in the benchmark's JVM, subscriber in a JVM of
 * its own: the most the broker carries between two clients on this machine (throughput: messages back to back,
 * from the first publish to the last receipt, after a warm-up) and its latency at a paced rate.
 */
final class BareClientsBench {
    /** One broker's figures. */
    record Row(String broker, double messagesPerSecond, ForkedSubscriber.Result flood, int rate,
            ForkedSubscriber.Result paced) {
    }

    /** How long a subscriber waits for the messages it expects (then it reports what came: complete=false). */
    private static final long RESULT_TIMEOUT_S = 120;

    private final Settings settings;

    BareClientsBench(Settings settings) {
        this.settings = settings;
    }

    Row run(String brokerName, BrokerAddress broker) throws Exception {
        String topic = "bench/bare/" + System.nanoTime();
        int warmup = settings.floodWarmup();
        int count = warmup + settings.floodMessages();
        ForkedSubscriber.Result flood;
        try (ForkedSubscriber sub = new ForkedSubscriber(broker, topic, "bench-sub", count, warmup, RESULT_TIMEOUT_S);
             Publisher pub = new Publisher(broker, topic, "bench-pub")) {
            sub.awaitReady(60);
            pub.flood(count);
            pub.drain();
            flood = sub.awaitResult(RESULT_TIMEOUT_S + 30);
        }
        double perSecond = settings.floodMessages() * 1e9 / Math.max(1, flood.lastNanos() - flood.firstMeasuredNanos());
        System.err.printf("  %s, bare clients: %,.0f messages/s (QoS 1, %,d after %,d warm-up)%n", brokerName,
                perSecond, settings.floodMessages(), warmup);

        int rate = settings.rate();
        int pacedWarmup = (int) (rate * settings.latencyWarmupSeconds());
        int pacedCount = pacedWarmup + (int) (rate * settings.latencySeconds());
        ForkedSubscriber.Result paced;
        String pacedTopic = topic + "/paced";
        try (ForkedSubscriber sub = new ForkedSubscriber(broker, pacedTopic, "bench-sub-paced", pacedCount,
                pacedWarmup, RESULT_TIMEOUT_S);
             Publisher pub = new Publisher(broker, pacedTopic, "bench-pub-paced")) {
            sub.awaitReady(60);
            pub.paced(pacedCount, rate);
            pub.drain();
            paced = sub.awaitResult(RESULT_TIMEOUT_S + 30);
        }
        System.err.printf("  %s, bare clients at %,d/s: p50 %s ms, p99 %s ms%n", brokerName, rate,
                LatencyStats.millis(paced.latency().p50Nanos()), LatencyStats.millis(paced.latency().p99Nanos()));
        return new Row(brokerName, perSecond, flood, rate, paced);
    }
}
