package eu.brain.iot.bms.impl;

import java.util.PriorityQueue;

/**
 * A {@link Scheduler} with virtual time for unit tests: tasks run when the test calls {@link #runDue()} or
 * {@link #advance}, on the test's thread, in time order. Thread-safe, so that publishers on other threads may
 * submit tasks.
 */
final class ManualScheduler implements Scheduler {

    private record Task(long due, long seq, Runnable run) {
    }

    private final PriorityQueue<Task> queue = new PriorityQueue<>((a, b) -> a.due != b.due
            ? Long.compare(a.due, b.due) : Long.compare(a.seq, b.seq));
    private long now = 1_000_000;
    private long seq;
    private boolean closed;

    @Override
    public synchronized void execute(Runnable task) {
        schedule(task, 0);
    }

    @Override
    public synchronized void schedule(Runnable task, long delayMillis) {
        if (!closed) {
            queue.add(new Task(now + Math.max(0, delayMillis), seq++, task));
        }
    }

    @Override
    public void every(long periodMillis, Runnable task) {
        schedule(new Runnable() {
            @Override
            public void run() {
                task.run();
                schedule(this, periodMillis);
            }
        }, periodMillis);
    }

    @Override
    public synchronized long now() {
        return now;
    }

    @Override
    public synchronized void close() {
        closed = true;
        queue.clear();
    }

    /** Run every task due now, including those they submit for now. */
    void runDue() {
        while (true) {
            Task next;
            synchronized (this) {
                next = queue.peek();
                if (next == null || next.due > now) {
                    return;
                }
                queue.poll();
            }
            next.run.run();
        }
    }

    /** Move the clock forward step by step, running what falls due on the way. */
    void advance(long millis) {
        long end;
        synchronized (this) {
            end = now + millis;
        }
        while (true) {
            runDue();
            synchronized (this) {
                Task next = queue.peek();
                if (next == null || next.due > end) {
                    now = end;
                    break;
                }
                now = next.due;
            }
        }
        runDue();
    }
}
