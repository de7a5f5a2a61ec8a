package eu.brain.iot.node.state;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Dictionary;
import java.util.Hashtable;
import java.util.concurrent.Callable;

import org.osgi.annotation.bundle.Capability;
import org.osgi.framework.BundleContext;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;

/**
 * The node's state folder ({@link StateFolder}), locked for as long as the node runs ({@link StateLock}). When the
 * lock is held by another node, or the folder cannot be used, it says so (which folder, which process holds it, what
 * to pass instead) and ends the node with exit code 1; the node's ready line waits for this component's
 * {@link StateHeld} service, which exists only while the lock is held, so a refused node never says it is ready.
 * It sets the system property {@value StateFolder#STATE} to the folder when it was not set, for the node's other
 * parts.
 * <p>
 * Threads: activated and deactivated by SCR, one at a time; {@link #lock} is written at activation only.
 */
// The StateHeld service is registered from code (only once the lock is held), so DS cannot declare it: declare it here,
// so that the node's resolver sees that this bundle provides what ReadyReporter requires.
@Capability(namespace = "osgi.service", attribute = "objectClass:List<String>=\"eu.brain.iot.node.state.StateHeld\"")
@Component(immediate = true)
public final class NodeState {

    private final StateLock lock;
    private final org.osgi.framework.ServiceRegistration<StateHeld> held;

    @Activate
    public NodeState(BundleContext context) {
        StateLock taken = null;
        Path folder = null;
        String problem;
        try {
            String name = StateFolder.name(context::getProperty);
            folder = StateFolder.of(context::getProperty, System::getenv);
            taken = StateLock.take(folder, "process " + ProcessHandle.current().pid() + " (node \"" + name + "\")");
            problem = null;
        } catch (IllegalArgumentException e) {
            problem = e.getMessage();
        } catch (StateLock.Held e) {
            problem = "the state folder " + folder + " is in use by another node: " + e.holder() + " holds "
                    + folder.resolve(StateLock.FILE) + ". Each node needs a state folder of its own: stop that node,"
                    + " or start this one with --state=DIR (a folder of its own; -D" + StateFolder.STATE + "=DIR) or"
                    + " --name=NAME (another name, which has another default folder)";
        } catch (IOException e) {
            problem = "the state folder " + folder + " cannot be used (" + e + "): make it writable, or start with"
                    + " --state=DIR (-D" + StateFolder.STATE + "=DIR) naming a folder this user can write";
        }
        this.lock = taken;
        if (taken == null) {
            System.out.println("fabric node: NOT started: " + problem);
            exitWith(context, 1);
            this.held = null;
            return;
        }
        if (System.getProperty(StateFolder.STATE) == null) {
            System.setProperty(StateFolder.STATE, folder.toString());
        }
        this.held = context.registerService(StateHeld.class, new StateHeld(folder), null);
    }

    @Deactivate
    void deactivate() throws IOException {
        if (held != null) {
            try {
                held.unregister();
            } catch (IllegalStateException e) {
                // gone with the bundle already
            }
        }
        if (lock != null) {
            lock.close();
        }
    }

    /** Hands the exit code to bnd's launcher (a main.thread Callable), which stops the framework and exits with it. */
    private static void exitWith(BundleContext context, int status) {
        Dictionary<String, Object> properties = new Hashtable<>();
        properties.put("main.thread", Boolean.TRUE);
        context.registerService(Callable.class, new ExitCode(status), properties);
    }

    /** A named class: bnd's launcher checks the main thread service's declared type, {@code Callable<Integer>}. */
    private static final class ExitCode implements Callable<Integer> {
        private final int status;

        ExitCode(int status) {
            this.status = status;
        }

        @Override
        public Integer call() {
            return status;
        }
    }
}
