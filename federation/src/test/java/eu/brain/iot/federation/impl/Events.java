package eu.brain.iot.federation.impl;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.eventing.api.SmartBehaviour;

/** Event types and behaviours of the multi-node tests. */
final class Events {

    private Events() {
    }

    public static class Moved extends BrainIoTEvent {
        public String robotId;
        public long seq;

        public Moved() {
        }

        Moved(String robotId, long seq) {
            this.robotId = robotId;
            this.seq = seq;
        }
    }

    public static class Docked extends Moved {
        public int dock;

        public Docked() {
        }

        Docked(String robotId, long seq, int dock) {
            super(robotId, seq);
            this.dock = dock;
        }
    }

    /** No behaviour anywhere consumes it. */
    public static class Nobody extends BrainIoTEvent {
        public int x;
    }

    /** Keeps every event it receives, in order. */
    static final class Recorder implements SmartBehaviour<Moved> {
        final List<Moved> got = new CopyOnWriteArrayList<>();
        /** Set when its node "crashes" (under this object's monitor): a dead process runs no behaviour. */
        private boolean dead;

        @Override
        public synchronized void notify(Moved event) {
            if (!dead) {
                got.add(event);
            }
        }

        /** Kill the node this behaviour runs in, as kill -9 would: from this instant it sees no event. */
        synchronized void dieWith(TestNode node) {
            dead = true;
            node.crash();
        }

        List<Long> seqs() {
            return got.stream().map(m -> m.seq).toList();
        }
    }
}
