package eu.brain.iot.bms.impl;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicInteger;

import org.osgi.util.promise.Deferred;
import org.osgi.util.promise.Promise;
import org.osgi.util.promise.PromiseFactory;

import eu.brain.iot.bis.api.BehaviourCandidate;
import eu.brain.iot.bis.api.BundleInstaller;
import eu.brain.iot.bis.api.InstallException;
import eu.brain.iot.bis.api.InstallRequest;
import eu.brain.iot.bis.api.InstalledBehaviour;

/**
 * A {@link BundleInstaller} for unit tests of the BMS core: candidates by consumed type, and every install request
 * kept with its {@link Deferred} so that the test decides when and how it ends. The real installer is tested in
 * bis/ and, with the BMS, in itests/.
 */
final class FakeInstaller implements BundleInstaller {

    record Request(InstallRequest request, Deferred<InstalledBehaviour> result) {
        void succeed() {
            InstalledBehaviour b = new InstalledBehaviour();
            b.symbolicName = request.symbolicName;
            b.version = request.versionRange.substring(1, request.versionRange.indexOf(','));
            b.state = "ACTIVE";
            b.consumed = request.consumedTypes;
            result.resolve(b);
        }

        void fail(InstallException.Problem problem, String message) {
            result.fail(new InstallException(problem, message));
        }
    }

    /** Callbacks run on the thread that resolves, as the test expects; they only queue work for the BMS. */
    private final PromiseFactory promises = new PromiseFactory(PromiseFactory.inlineExecutor());
    final Map<String, List<BehaviourCandidate>> candidates = new HashMap<>();
    final List<Request> requests = new CopyOnWriteArrayList<>();
    final List<InstalledBehaviour> active = new CopyOnWriteArrayList<>();
    final AtomicInteger finds = new AtomicInteger();
    /** The event fields each {@code find(types, event)} was given, in call order. */
    final List<Map<String, ?>> findEvents = new CopyOnWriteArrayList<>();
    /** When set, find answers later: the test resolves it. */
    volatile Deferred<List<BehaviourCandidate>> pendingFind;
    boolean remote;
    /** When set, every install request fails at once with it. */
    volatile InstallException failEveryInstall;
    /** What the installer says it is doing. */
    volatile List<String> activities = List.of();

    void offer(String type, String symbolicName, String version) {
        BehaviourCandidate c = new BehaviourCandidate();
        c.symbolicName = symbolicName;
        c.version = version;
        c.consumed = List.of(type);
        c.repository = "file:/test/index.xml";
        candidates.computeIfAbsent(type, t -> new ArrayList<>()).add(c);
    }

    @Override
    public Promise<List<BehaviourCandidate>> find(List<String> consumedTypes, Map<String, ?> event) {
        findEvents.add(event);
        return find(consumedTypes);
    }

    @Override
    public Promise<List<BehaviourCandidate>> find(List<String> consumedTypes) {
        finds.incrementAndGet();
        if (remote) {
            Deferred<List<BehaviourCandidate>> d = promises.deferred();
            pendingFind = d;
            return d.getPromise();
        }
        List<BehaviourCandidate> found = new ArrayList<>();
        for (String type : consumedTypes) {
            found.addAll(candidates.getOrDefault(type, List.of()));
        }
        return promises.resolved(found);
    }

    @Override
    public Promise<InstalledBehaviour> install(InstallRequest request) {
        Deferred<InstalledBehaviour> d = promises.deferred();
        requests.add(new Request(request, d));
        InstallException failure = failEveryInstall;
        if (failure != null) {
            d.fail(failure);
        }
        return d.getPromise();
    }

    Request last() {
        return requests.get(requests.size() - 1);
    }

    @Override
    public Promise<InstalledBehaviour> uninstall(String symbolicName, String reason, boolean byOperator) {
        throw new UnsupportedOperationException("not used by the BMS");
    }

    @Override
    public void allow(String symbolicName) {
        throw new UnsupportedOperationException("not used by the BMS");
    }

    @Override
    public List<InstalledBehaviour> installed() {
        return List.copyOf(active);
    }

    @Override
    public List<String> activities() {
        return activities;
    }
}
