package eu.brain.iot.federation.impl;

import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.Function;

import org.osgi.util.promise.Promise;
import org.osgi.util.promise.Promises;

import eu.brain.iot.bis.api.BehaviourCandidate;
import eu.brain.iot.bis.api.BundleInstaller;
import eu.brain.iot.bis.api.InstallRequest;
import eu.brain.iot.bis.api.InstalledBehaviour;

/**
 * A node's own installer in the multi-node tests: it offers the candidates it is given (from memory, a resolved
 * promise, as the real one), and an install does what the test says (typically: register a behaviour with the
 * node's bus, as the real installer's bundle would). Thread-safe: lists are copy-on-write, fields volatile.
 */
final class FakeInstaller implements BundleInstaller {

    /** Candidates by consumed type. */
    volatile Map<String, BehaviourCandidate> offers = Map.of();
    /** What {@code find} answers instead, when set (e.g. a promise that never resolves: a node that is slow). */
    volatile Promise<List<BehaviourCandidate>> findAnswer;
    volatile Function<InstallRequest, Promise<InstalledBehaviour>> onInstall = r -> Promises
            .resolved(installed(r.symbolicName));
    final List<InstallRequest> installs = new CopyOnWriteArrayList<>();
    final List<InstalledBehaviour> done = new CopyOnWriteArrayList<>();

    static BehaviourCandidate candidate(String symbolicName, String... consumed) {
        BehaviourCandidate c = new BehaviourCandidate();
        c.symbolicName = symbolicName;
        c.version = "1.0.0";
        c.consumed = List.of(consumed);
        c.repository = "file:/test/index.xml";
        return c;
    }

    static InstalledBehaviour installed(String symbolicName) {
        InstalledBehaviour b = new InstalledBehaviour();
        b.symbolicName = symbolicName;
        b.version = "1.0.0";
        b.state = "ACTIVE";
        return b;
    }

    @Override
    public Promise<List<BehaviourCandidate>> find(List<String> consumedTypes) {
        Promise<List<BehaviourCandidate>> instead = findAnswer;
        if (instead != null) {
            return instead;
        }
        return Promises.resolved(consumedTypes.stream().map(offers::get).filter(c -> c != null).distinct().toList());
    }

    @Override
    public Promise<InstalledBehaviour> install(InstallRequest request) {
        installs.add(request);
        return onInstall.apply(request).onSuccess(done::add);
    }

    @Override
    public Promise<InstalledBehaviour> uninstall(String symbolicName, String reason, boolean byOperator) {
        return Promises.failed(new UnsupportedOperationException());
    }

    @Override
    public void allow(String symbolicName) {
    }

    @Override
    public List<InstalledBehaviour> installed() {
        return List.copyOf(done);
    }
}
