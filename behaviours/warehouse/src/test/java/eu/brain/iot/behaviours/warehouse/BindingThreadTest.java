package eu.brain.iot.behaviours.warehouse;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.time.Duration;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;

/** The binding's looks come once per period from start to start, whatever each look takes. */
class BindingThreadTest {

    private static final long PERIOD_MILLIS = 40;
    /** What each look keeps its thread busy (three quarters of the period). */
    private static final long LOOK_NANOS = TimeUnit.MILLISECONDS.toNanos(30);

    @Test
    void aLookTakingMostOfThePeriodDelaysTheNextOneNot() {
        List<Long> starts = new CopyOnWriteArrayList<>();
        try (BindingThread thread = new BindingThread("test-binding", 1, PERIOD_MILLIS)) {
            Future<?> looks = thread.start(() -> {
                long start = System.nanoTime();
                starts.add(start);
                while (System.nanoTime() - start < LOOK_NANOS) {
                    Thread.onSpinWait(); // the look's work
                }
            });
            await().atMost(Duration.ofSeconds(20)).until(() -> starts.size() >= 26);
            looks.cancel(false);
            int seen = starts.size();
            long lastStart = starts.get(seen - 1);
            await().atMost(Duration.ofSeconds(5)).until(() -> System.nanoTime() - lastStart
                    > TimeUnit.MILLISECONDS.toNanos(5 * PERIOD_MILLIS));
            assertThat(starts).as("no look after the cancel").hasSizeLessThanOrEqualTo(seen + 1);
        }
        double meanMillis = (starts.get(25) - starts.get(5)) / 20 / 1e6;
        // a fixed delay after each look: 40 + 30 = 70 ms from start to start
        assertThat(meanMillis).as("mean time between the starts of two looks").isLessThan(55);
    }

    @Test
    void aLookThatThrowsIsFollowedByTheNext() {
        List<Long> starts = new CopyOnWriteArrayList<>();
        try (BindingThread thread = new BindingThread("test-binding", 1, 10)) {
            thread.start(() -> {
                starts.add(System.nanoTime());
                if (starts.size() == 1) {
                    throw new IllegalStateException("the first look fails");
                }
            });
            await().atMost(Duration.ofSeconds(10)).until(() -> starts.size() >= 3);
        }
    }
}
