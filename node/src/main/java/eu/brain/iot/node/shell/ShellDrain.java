package eu.brain.iot.node.shell;

import java.time.Duration;
import java.util.Arrays;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;

import org.osgi.framework.BundleContext;
import org.osgi.framework.BundleEvent;
import org.osgi.framework.Constants;
import org.osgi.framework.SynchronousBundleListener;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;

/**
 * Lets the shell command that stopped the node return before the node stops the Gogo shell.
 * <p>
 * {@code stop 0} typed in the shell makes the framework stop on a thread of its own while the shell's console thread
 * is still inside that command; the framework stops the shell first (it has the highest start level), and the shell
 * interrupts its console thread, which then prints {@code gogo: InterruptedException: null} on the way out. When the
 * system bundle starts stopping, this listener (run synchronously, on the thread that stops the framework, before any
 * bundle is stopped) waits until no console thread is inside a command, for at most {@link #PATIENCE}: a command
 * that stops the node returns at once, and a command that never returns does not keep the node from stopping.
 * <p>
 * Threads: {@link #bundleChanged} runs on whichever thread stops the framework; the listener holds no state.
 */
@Component(service = {})
public final class ShellDrain implements SynchronousBundleListener {

    /** The longest the framework's stop waits for a running shell command. */
    static final Duration PATIENCE = Duration.ofSeconds(3);
    private static final long POLL_NANOS = TimeUnit.MILLISECONDS.toNanos(5);
    /** The Gogo shell's console loop, and the runtime's method that runs one command line. */
    static final String CONSOLE_LOOP = "org.apache.felix.gogo.shell.Console";
    static final String EXECUTE = "org.apache.felix.gogo.runtime.CommandSessionImpl";

    private final BundleContext context;

    @Activate
    public ShellDrain(BundleContext context) {
        this.context = context;
        context.addBundleListener(this);
    }

    @Deactivate
    void stop() {
        context.removeBundleListener(this);
    }

    @Override
    public void bundleChanged(BundleEvent event) {
        if (event.getType() == BundleEvent.STOPPING && event.getBundle().getBundleId() == Constants.SYSTEM_BUNDLE_ID) {
            awaitNoCommand(PATIENCE);
        }
    }

    /** Waits until no console thread (other than this one) is inside a command; false if the patience ran out. */
    static boolean awaitNoCommand(Duration patience) {
        long deadline = System.nanoTime() + patience.toNanos();
        while (commandRunning()) {
            if (System.nanoTime() - deadline >= 0) {
                return false;
            }
            LockSupport.parkNanos(POLL_NANOS);
        }
        return true;
    }

    static boolean commandRunning() {
        Thread self = Thread.currentThread();
        for (Map.Entry<Thread, StackTraceElement[]> e : Thread.getAllStackTraces().entrySet()) {
            if (e.getKey() != self && inCommand(e.getValue())) {
                return true;
            }
        }
        return false;
    }

    /** A console thread inside a command: its stack holds the console loop and a command's execution. */
    static boolean inCommand(StackTraceElement[] stack) {
        return Arrays.stream(stack).anyMatch(f -> f.getClassName().equals(CONSOLE_LOOP))
                && Arrays.stream(stack).anyMatch(f -> f.getClassName().equals(EXECUTE)
                        && f.getMethodName().equals("execute"));
    }
}
