package eu.brain.iot.eventing.integration;

import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicInteger;

import eu.brain.iot.eventing.api.SmartBehaviour;

/** A behaviour that counts the events it gets and blocks in each one until the test opens its gate. */
final class GatedBehaviour implements SmartBehaviour<PositionEvent> {
    private final CountDownLatch gate = new CountDownLatch(1);
    private final AtomicInteger received = new AtomicInteger();

    @Override
    public void notify(PositionEvent event) {
        received.incrementAndGet();
        try {
            gate.await();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    int received() {
        return received.get();
    }

    void open() {
        gate.countDown();
    }
}
