package eu.brain.iot.bms.impl;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.BiConsumer;

import org.osgi.util.promise.Promise;
import org.osgi.util.promise.Promises;

import eu.brain.iot.bis.api.BundleInstaller;
import eu.brain.iot.bis.api.InstallRequest;
import eu.brain.iot.bis.api.InstalledBehaviour;

/**
 * The install requests in flight, one per behaviour (symbolic name): event types that need the same behaviour, and a
 * {@link Revivals revival} of it, share one request, as the installer would turn them into one install anyway; the
 * BMS's history then records one outcome. Owned by the BMS's thread (no lock): requests are made there, and the
 * installer's answers only queue {@code answered} there.
 */
final class InstallJobs {

    private final BundleInstaller installer;
    private final Scheduler scheduler;
    private final Map<String, InstallJob> bySymbolicName = new HashMap<>();
    private long next = 1;

    InstallJobs(BundleInstaller installer, Scheduler scheduler) {
        this.installer = installer;
        this.scheduler = scheduler;
    }

    /** @return the request in flight for this behaviour, or {@code null} */
    InstallJob inFlight(String symbolicName) {
        return bySymbolicName.get(symbolicName);
    }

    /**
     * Asks the installer for exactly this behaviour (an automatic request, never an operator's); its answer is
     * passed to {@code answered} on the BMS's thread, the job no longer in flight by then.
     *
     * @param node the fabric node the installer chose for it ({@code BehaviourCandidate.node}), {@code null} for
     *        this node
     */
    InstallJob start(String symbolicName, String version, String node, List<String> consumedTypes, String kind,
            String reason, boolean revival, BiConsumer<InstallJob, Promise<InstalledBehaviour>> answered) {
        InstallJob job = new InstallJob(next++, symbolicName, symbolicName + " " + version, kind, reason,
                new ArrayList<>(), revival);
        bySymbolicName.put(symbolicName, job);
        InstallRequest request = new InstallRequest();
        request.symbolicName = symbolicName;
        request.versionRange = version == null ? null : "[" + version + "," + version + "]";
        request.consumedTypes = consumedTypes;
        request.reason = reason;
        request.operator = false;
        request.node = node;
        Promise<InstalledBehaviour> result;
        try {
            result = installer.install(request);
        } catch (RuntimeException e) {
            result = Promises.failed(e);
        }
        Promise<InstalledBehaviour> answer = result;
        answer.onResolve(() -> scheduler.execute(() -> {
            bySymbolicName.remove(symbolicName, job);
            answered.accept(job, answer);
        }));
        return job;
    }
}
