package eu.brain.iot.behaviours.warehouse.traffic;

/**
 * Which way one door lets robots through: its two directions alternate in batches sized to the queue. A batch
 * starts when the door turns to a direction and is as large as the queue waiting that way at that moment; the door
 * turns once the batch has passed (or nobody waits that way any more) and robots wait on the other side. So a long
 * queue is served in one go (robots following each other through a door need 2 steps each, a change of direction
 * 4) and a lone robot on the other side waits for at most one batch. Owned by the planner's thread.
 */
public final class DoorBatches {
    /** The two ways through a door: towards the unload area (out) and back from it (in). */
    public enum Way { OUT, IN }

    private Way serving = Way.OUT;
    private int batchLeft;
    /** Whether a batch has begun (at first the door serves whichever side has a queue). */
    private boolean started;

    /** @return the direction served now */
    public Way serving() {
        return serving;
    }

    /** @return robots of the current batch still to pass */
    public int batchLeft() {
        return batchLeft;
    }

    /**
     * Looks at the queues and decides the way served in this step.
     *
     * @param waitingOut robots waiting (or driving up) to go out through the door
     * @param waitingIn  robots waiting (or driving up) to come in
     * @return the direction served
     */
    public Way decide(int waitingOut, int waitingIn) {
        int here = serving == Way.OUT ? waitingOut : waitingIn;
        int there = serving == Way.OUT ? waitingIn : waitingOut;
        boolean batchOver = started && batchLeft <= 0 || here == 0;
        if (batchOver && there > 0) {
            serving = serving == Way.OUT ? Way.IN : Way.OUT;
            batchLeft = there;
            started = true;
        } else if (batchLeft <= 0 && here > 0) {
            batchLeft = here;
            started = true;
        }
        return serving;
    }

    /** A robot went through the door in the given direction. */
    public void passed(Way way) {
        if (way == serving && batchLeft > 0) {
            batchLeft--;
        }
    }
}
