package eu.brain.iot.bis.impl.install;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;

import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.osgi.framework.BundleException;
import org.osgi.framework.Constants;

import eu.brain.iot.bis.api.InstallException;
import eu.brain.iot.bis.api.InstallException.Problem;
import eu.brain.iot.bis.impl.journal.BehaviourRecord;
import eu.brain.iot.bis.impl.journal.BundleFact;

/**
 * Starts again a behaviour the installer installed that is no longer active (its bundle stopped, by a failure or by
 * Gogo's {@code stop}; or active without its smart behaviours, a component not satisfied), with the bundles it needs,
 * and waits until the bus has its smart behaviours. Stateless; runs on the installer's thread, which it blocks while
 * it waits.
 */
final class Restarter {

    private final BundleContext context;
    private final Activation activation;
    private final long activationTimeoutMillis;
    private final Consumer<String> info;

    Restarter(BundleContext context, Activation activation, long activationTimeoutMillis, Consumer<String> info) {
        this.context = context;
        this.activation = activation;
        this.activationTimeoutMillis = activationTimeoutMillis;
        this.info = info;
    }

    /** The bundle's state for people, saying when an active one lacks its smart behaviours. */
    static String stateForPeople(Bundle own) {
        return own.getState() == Bundle.ACTIVE && !Activation.hasBehaviours(own)
                ? "ACTIVE without its smart behaviours registered"
                : Dtos.state(own);
    }

    /**
     * Starts the behaviour's bundles that are not active (dependencies first), then waits for the bus.
     *
     * @return {@code false} when it was active with its smart behaviours registered: nothing to do
     */
    boolean ensureActive(BehaviourRecord record, Bundle own) throws InstallException, InterruptedException {
        if (own.getState() == Bundle.ACTIVE && Activation.hasBehaviours(own)) {
            return false;
        }
        List<BundleFact> startOrder = new ArrayList<>(record.bundles());
        startOrder.add(startOrder.remove(0)); // dependencies first, the behaviour last
        for (BundleFact f : startOrder) {
            Bundle b = context.getBundle(f.location());
            if (b != null && b.getState() != Bundle.ACTIVE && b.getHeaders().get(Constants.FRAGMENT_HOST) == null) {
                try {
                    b.start();
                } catch (BundleException e) {
                    throw new InstallException(Problem.START_FAILED, f.symbolicName() + " (bundle " + b.getBundleId()
                            + ") is installed but failed to start again: " + e.getMessage(), e);
                }
            }
        }
        if (activation.await(own, activationTimeoutMillis) == null) {
            throw new InstallException(Problem.ACTIVATION_TIMEOUT, record.symbolicName() + " was started again, but"
                    + " no smart behaviour of it was registered with the bus within " + activationTimeoutMillis
                    + " ms (" + activation.missing(own) + "; " + ComponentStates.of(context, own) + "; 'scr:info' in the"
                    + " shell says more)");
        }
        info.accept("restarted " + record.symbolicName() + " " + record.version());
        return true;
    }
}
