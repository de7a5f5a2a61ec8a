package eu.brain.iot.eventing.impl;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadInfo;
import java.lang.management.ThreadMXBean;

/**
 * What a delivery worker's thread is doing, as far as the JVM can tell, for the {@link StallWatchdog}.
 * <p>
 * The question is whether a worker that makes no progress is held by its behaviour (waiting, in blocking I/O,
 * computing) or merely not scheduled: on a machine with more runnable threads than cores, a running thread can
 * wait tens of milliseconds for a core, and adding workers then would only add threads when cores are short.
 * Java reports both as {@code RUNNABLE}; the thread's CPU time and whether it is in native code help tell them
 * apart (neither is proof, see {@link StallWatchdog}, hence the longer threshold for running threads).
 */
final class ThreadActivity {

    /** No CPU clock for threads in this JVM. */
    static final long UNKNOWN = -1;

    private static final ThreadMXBean THREADS = ManagementFactory.getThreadMXBean();
    private static final boolean CPU_CLOCK = THREADS.isThreadCpuTimeSupported() && THREADS.isThreadCpuTimeEnabled();

    private ThreadActivity() {
    }

    /** Waiting on a lock, a condition, a sleep or a park: certainly held by what it runs, not by the machine. */
    static boolean waiting(Thread thread) {
        Thread.State state = thread.getState();
        return state == Thread.State.WAITING || state == Thread.State.TIMED_WAITING || state == Thread.State.BLOCKED;
    }

    /**
     * In native code, which for a behaviour means I/O (sockets, files) or a native library. The snapshot has no
     * stack, so the JVM takes it without stopping other threads.
     */
    static boolean inNative(Thread thread) {
        ThreadInfo info = THREADS.getThreadInfo(thread.getId());
        return info != null && info.isInNative();
    }

    /** @return the CPU time the thread has used (ns), or {@link #UNKNOWN} */
    static long cpuNanos(Thread thread) {
        return CPU_CLOCK ? THREADS.getThreadCpuTime(thread.getId()) : UNKNOWN;
    }
}
