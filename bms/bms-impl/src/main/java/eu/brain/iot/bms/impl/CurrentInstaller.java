package eu.brain.iot.bms.impl;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;

import org.osgi.util.promise.Promise;
import org.osgi.util.promise.Promises;

import eu.brain.iot.bis.api.BehaviourCandidate;
import eu.brain.iot.bis.api.BundleInstaller;
import eu.brain.iot.bis.api.InstallException;
import eu.brain.iot.bis.api.InstallException.Problem;
import eu.brain.iot.bis.api.InstallRequest;
import eu.brain.iot.bis.api.InstalledBehaviour;

/**
 * The best-ranked {@link BundleInstaller} at each call: the BMS follows the installers as they come and go without
 * being restarted, so the events the bus holds for it and its installs in flight are kept. A node's own installer
 * is there from the start; a fabric's installer (higher ranking, it asks the other nodes which one installs) takes
 * its place while the node is a member of a fabric, and gives it back when the node leaves. A request made through
 * one installer is answered by that one (its promise), even when another has taken its place meanwhile.
 * <p>
 * Threads: SCR binds and unbinds (any thread, serialised by the monitor); the BMS's and publishers' threads call
 * and read {@link #installers}, an immutable list, best first, replaced as a whole.
 */
final class CurrentInstaller implements BundleInstaller {

    /** An installer and its ranking, as DS gives them. */
    record Ranked(BundleInstaller installer, int ranking, long serviceId) {
    }

    /** The OSGi order: highest ranking, then lowest service id. */
    private static final Comparator<Ranked> BEST_FIRST = Comparator.comparingInt(Ranked::ranking).reversed()
            .thenComparingLong(Ranked::serviceId);

    private volatile List<Ranked> installers = List.of();

    synchronized void add(BundleInstaller installer, int ranking, long serviceId) {
        List<Ranked> next = new ArrayList<>(installers);
        next.removeIf(r -> r.serviceId() == serviceId);
        next.add(new Ranked(installer, ranking, serviceId));
        next.sort(BEST_FIRST);
        installers = List.copyOf(next);
    }

    synchronized void remove(long serviceId) {
        List<Ranked> next = new ArrayList<>(installers);
        next.removeIf(r -> r.serviceId() == serviceId);
        installers = List.copyOf(next);
    }

    /** @return the best-ranked installer, or {@code null} when none is bound */
    BundleInstaller current() {
        List<Ranked> now = installers;
        return now.isEmpty() ? null : now.get(0).installer();
    }

    private static <T> Promise<T> none() {
        return Promises.failed(new InstallException(Problem.CLOSED, "no Bundle Installer Service is registered"));
    }

    @Override
    public Promise<List<BehaviourCandidate>> find(List<String> consumedTypes) {
        BundleInstaller i = current();
        return i == null ? none() : i.find(consumedTypes);
    }

    @Override
    public Promise<List<BehaviourCandidate>> find(List<String> consumedTypes, Map<String, ?> event) {
        BundleInstaller i = current();
        return i == null ? none() : i.find(consumedTypes, event);
    }

    @Override
    public Promise<InstalledBehaviour> install(InstallRequest request) {
        BundleInstaller i = current();
        return i == null ? none() : i.install(request);
    }

    @Override
    public Promise<InstalledBehaviour> uninstall(String symbolicName, String reason, boolean byOperator) {
        BundleInstaller i = current();
        return i == null ? none() : i.uninstall(symbolicName, reason, byOperator);
    }

    @Override
    public void allow(String symbolicName) {
        BundleInstaller i = current();
        if (i != null) {
            i.allow(symbolicName);
        }
    }

    @Override
    public List<InstalledBehaviour> installed() {
        BundleInstaller i = current();
        return i == null ? List.of() : i.installed();
    }

    @Override
    public List<String> activities() {
        BundleInstaller i = current();
        return i == null ? List.of() : i.activities();
    }
}
