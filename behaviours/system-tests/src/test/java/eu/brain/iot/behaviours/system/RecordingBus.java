package eu.brain.iot.behaviours.system;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Random;

import eu.brain.iot.behaviours.events.TransitionFired;
import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.eventing.api.EventBus;
import eu.brain.iot.eventing.api.SmartBehaviour;

/**
 * A stand-in for the event bus that records every published event with its cause (the event being delivered when
 * it was published; null for the environment's), for checking runs of the generated behaviours against the SMC
 * semantics ({@link BusRunChecker}). Each behaviour gets every event but the trace ({@code TransitionFired}, which
 * none consumes; a behaviour ignores the types it does not consume) in a queue of its own, in publish order, like
 * the fabric's bus. Two schedules:
 * <ul>
 * <li>in order ({@code random} null): one event at a time, to every behaviour, in publish order (as {@link TestBus});
 * <li>interleaved: at each step one behaviour with queued events, chosen at random, takes its next event; the
 * environment may publish between any two deliveries ({@link #deliverOne}); so the behaviours see events in an
 * order the fabric's bus (one worker per behaviour at a time, several workers) may also produce.
 * </ul>
 * Owned by the test thread.
 */
final class RecordingBus implements EventBus {

    /** An event and what was being delivered when it was published (null: the environment). */
    record Published(BrainIoTEvent event, BrainIoTEvent cause) {
    }

    private final Random random;
    private final List<SmartBehaviour<BrainIoTEvent>> behaviours = new ArrayList<>();
    private final List<ArrayDeque<BrainIoTEvent>> queues = new ArrayList<>();
    private final ArrayDeque<BrainIoTEvent> inOrder = new ArrayDeque<>();
    private final List<Published> log = new ArrayList<>();
    private BrainIoTEvent delivering;

    /** @param random the interleaving's random source, or null for the in-order schedule */
    RecordingBus(Random random) {
        this.random = random;
    }

    void register(SmartBehaviour<BrainIoTEvent> behaviour) {
        behaviours.add(behaviour);
        queues.add(new ArrayDeque<>());
    }

    @Override
    public void deliver(BrainIoTEvent event) {
        log.add(new Published(event, delivering));
        if (event instanceof TransitionFired) {
            return;
        }
        if (random == null) {
            inOrder.add(event);
            return;
        }
        queues.forEach(q -> q.add(event));
    }

    @Override
    public void deliver(String eventType, Map<String, Object> eventData) {
        throw new UnsupportedOperationException("the generated behaviours publish typed events");
    }

    @Override
    public boolean tryDeliver(BrainIoTEvent event) {
        deliver(event); // its queues have no bound: there is always room
        return true;
    }

    @Override
    public boolean tryDeliver(String eventType, Map<String, Object> eventData) {
        throw new UnsupportedOperationException("the generated behaviours publish typed events");
    }

    /** Delivers one queued event (in order: to every behaviour). @return false when nothing is queued */
    boolean deliverOne() {
        if (random == null) {
            BrainIoTEvent e = inOrder.poll();
            if (e == null) {
                return false;
            }
            for (int b = 0; b < behaviours.size(); b++) {
                notify(b, e);
            }
            return true;
        }
        List<Integer> ready = new ArrayList<>();
        for (int b = 0; b < queues.size(); b++) {
            if (!queues.get(b).isEmpty()) {
                ready.add(b);
            }
        }
        if (ready.isEmpty()) {
            return false;
        }
        int b = ready.get(random.nextInt(ready.size()));
        notify(b, queues.get(b).poll());
        return true;
    }

    private void notify(int b, BrainIoTEvent e) {
        delivering = e;
        try {
            behaviours.get(b).notify(e);
        } finally {
            delivering = null;
        }
    }

    void drain() {
        for (int guard = 0; deliverOne(); guard++) {
            if (guard > 100_000) {
                throw new AssertionError("the behaviours keep publishing");
            }
        }
    }

    List<Published> log() {
        return log;
    }
}
