package eu.brain.iot.probe;

import static org.awaitility.Awaitility.await;
import static org.junit.jupiter.api.Assertions.assertEquals;

import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.eventing.api.EventBus;
import java.lang.annotation.Annotation;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import org.junit.jupiter.api.Test;

/**
 * {@code consumer.timeout.s=0}: the publisher publishes at once, without looking for a consumer (the framework is
 * never asked: the bundle context is absent), so that an event nobody takes is left to the node's BMS.
 */
class ProbePublisherTest {
    private static final Duration DEADLINE = Duration.ofSeconds(10);

    /** A bus that keeps what it is given; called on the publisher's thread, read on the test's. */
    private static final class RecordingBus implements EventBus {
        final List<BrainIoTEvent> delivered = new CopyOnWriteArrayList<>();

        @Override
        public void deliver(BrainIoTEvent event) {
            delivered.add(event);
        }

        @Override
        public void deliver(String eventType, Map<String, Object> eventData) {
            throw new UnsupportedOperationException("the probe publishes typed events");
        }

        @Override
        public boolean tryDeliver(BrainIoTEvent event) {
            deliver(event);
            return true;
        }

        @Override
        public boolean tryDeliver(String eventType, Map<String, Object> eventData) {
            throw new UnsupportedOperationException("the probe publishes typed events");
        }
    }

    private static ProbePublisherConfig atOnce(String run, long count) {
        return new ProbePublisherConfig() {
            @Override
            public Class<? extends Annotation> annotationType() {
                return ProbePublisherConfig.class;
            }

            @Override
            public String run() {
                return run;
            }

            @Override
            public long count() {
                return count;
            }

            @Override
            public int rate() {
                return 0;
            }

            @Override
            public int consumer_timeout_s() {
                return ProbePublisher.PUBLISH_AT_ONCE;
            }
        };
    }

    @Test
    void publishesAtOnceWithoutAConsumer() throws InterruptedException {
        RecordingBus bus = new RecordingBus();
        ProbePublisher publisher = new ProbePublisher(bus, atOnce("install-1", 3), null);
        try {
            await("three probe events delivered").atMost(DEADLINE).until(() -> bus.delivered.size() == 3);
        } finally {
            publisher.stop();
        }
        for (int i = 0; i < 3; i++) {
            ProbeEvent e = (ProbeEvent) bus.delivered.get(i);
            assertEquals("install-1", e.run);
            assertEquals(i + 1, e.seq);
        }
    }
}
