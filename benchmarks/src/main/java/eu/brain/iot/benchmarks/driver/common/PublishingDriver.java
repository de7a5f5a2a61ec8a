package eu.brain.iot.benchmarks.driver.common;

import java.util.concurrent.locks.LockSupport;

import eu.brain.iot.benchmarks.spi.BusDriver;

/**
 * The publishing loops shared by every driver. Each driver bundle holds its own copy of this class, so each loop is
 * compiled against one bus only. Events carry a robot id, two coordinates and a time stamp: four small fields.
 */
public abstract class PublishingDriver implements BusDriver {

    protected static final String ROBOT_ID = "robot-7";

    /** Hand one event to the bus, from the calling thread. */
    protected abstract void publish(String robotId, int x, int y, long sentNanos);

    @Override
    public final void publishBurst(int count) {
        for (int i = 0; i < count; i++) {
            publish(ROBOT_ID, i, -i, i);
        }
    }

    @Override
    public final void publishPaced(int count, long intervalNanos) {
        long next = System.nanoTime();
        for (int i = 0; i < count; i++) {
            long wait;
            while ((wait = next - System.nanoTime()) > 0) {
                // Parking, not spinning: on 2 cores a spinning publisher would take a core from the consumers.
                LockSupport.parkNanos(wait);
            }
            publish(ROBOT_ID, i, -i, System.nanoTime());
            next += intervalNanos;
        }
    }
}
