package eu.brain.iot.bis.impl.install;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.RejectedExecutionException;
import java.util.function.Consumer;
import java.util.function.Supplier;

import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.osgi.framework.BundleException;
import org.osgi.util.promise.Deferred;
import org.osgi.util.promise.Promise;
import org.osgi.util.promise.PromiseFactory;
import org.osgi.service.resolver.Resolver;

import eu.brain.iot.bis.api.BehaviourCandidate;
import eu.brain.iot.bis.api.BundleInstaller;
import eu.brain.iot.bis.api.InstallException;
import eu.brain.iot.bis.api.InstallException.Problem;
import eu.brain.iot.bis.api.InstallRequest;
import eu.brain.iot.bis.api.InstalledBehaviour;
import eu.brain.iot.bis.impl.journal.BehaviourRecord;
import eu.brain.iot.bis.impl.journal.BundleFact;
import eu.brain.iot.bis.impl.journal.Journal;
import eu.brain.iot.bis.impl.repo.BehaviourResource;
import eu.brain.iot.bis.impl.repo.Repositories;
import eu.brain.iot.bis.impl.repo.UrlReader;
import eu.brain.iot.eventing.monitoring.api.EventBusStatistics;

/**
 * The local {@link BundleInstaller}. Requests are answered at once with a promise; installs, uninstalls and
 * allowances run one at a time on the installer's single thread ({@code executor}), so that each transaction sees
 * the framework as the previous one left it. Requests for a behaviour already being installed get that install's
 * promise.
 * <p>
 * Threads: {@link #inflight} and {@link #closed} are guarded by {@code this}; the {@link Ledger} guards itself;
 * everything else is touched only on the installer's thread. Promise callbacks run on the promise factory's
 * callback executor, never on the installer's thread.
 */
public final class Installer implements BundleInstaller {

    private final BundleContext context;
    private final Repositories repositories;
    private final ChoicePolicy policy;
    private final Ledger ledger;
    private final Transaction transaction;
    private final Restarter restarter;
    private final ExecutorService executor;
    private final PromiseFactory promises;
    private final Consumer<String> warn;
    private final Consumer<String> info;
    private final Map<String, Promise<InstalledBehaviour>> inflight = new HashMap<>();
    /** Why a journal entry is not back: written on the installer's thread, read by Gogo. */
    private final Map<String, String> restoreProblems = new java.util.concurrent.ConcurrentHashMap<>();
    private boolean closed;
    /** Set on the installer's thread once the start's restore ran; read by the index reader's thread. */
    private volatile boolean restored;

    /** @param loaded what the journal held at start */
    public static Installer create(BundleContext context, Resolver resolver, Repositories repositories,
            UrlReader reader, Journal journal, Journal.State loaded, List<String> prefer, long activationTimeoutMillis,
            Supplier<EventBusStatistics> statistics, ExecutorService executor, PromiseFactory promises,
            Consumer<String> error, Consumer<String> warn, Consumer<String> info) {
        Ledger ledger = new Ledger(journal, loaded, error);
        Activation activation = new Activation(context, statistics);
        Transaction transaction = new Transaction(context, resolver, repositories, reader, activation,
                activationTimeoutMillis, warn);
        return new Installer(context, repositories, new ChoicePolicy(prefer), ledger, transaction,
                new Restarter(context, activation, activationTimeoutMillis, info), executor, promises, warn, info);
    }

    private Installer(BundleContext context, Repositories repositories, ChoicePolicy policy, Ledger ledger,
            Transaction transaction, Restarter restarter, ExecutorService executor, PromiseFactory promises,
            Consumer<String> warn, Consumer<String> info) {
        this.context = context;
        this.repositories = repositories;
        this.policy = policy;
        this.ledger = ledger;
        this.transaction = transaction;
        this.restarter = restarter;
        this.executor = executor;
        this.promises = promises;
        this.warn = warn;
        this.info = info;
    }

    @Override
    public Promise<List<BehaviourCandidate>> find(List<String> consumedTypes) {
        List<BehaviourCandidate> found = policy.byConsumedTypes(repositories.resources(), consumedTypes).stream()
                .map(BehaviourResource::candidate).toList();
        return promises.resolved(found);
    }

    @Override
    public Promise<InstalledBehaviour> install(InstallRequest request) {
        List<BehaviourResource> candidates;
        if (request.symbolicName != null && !request.symbolicName.isBlank()) {
            try {
                candidates = policy.byName(repositories.resources(), request.symbolicName, request.versionRange);
            } catch (IllegalArgumentException e) {
                return failed(Problem.NOT_FOUND, "versionRange '" + request.versionRange + "' is no OSGi version"
                        + " range (e.g. [1.0,2)): " + e.getMessage());
            }
        } else if (request.consumedTypes != null && !request.consumedTypes.isEmpty()) {
            candidates = policy.byConsumedTypes(repositories.resources(), request.consumedTypes);
        } else {
            return failed(Problem.NOT_FOUND, "an install request needs symbolicName or consumedTypes");
        }
        String what = request.symbolicName != null && !request.symbolicName.isBlank()
                ? request.symbolicName + (request.versionRange == null ? "" : " " + request.versionRange)
                : "a behaviour consuming " + request.consumedTypes;
        if (candidates.isEmpty()) {
            return failed(Problem.NOT_FOUND, "no repository offers " + what + " (indexes: " + indexes()
                    + "); add it to an index, or configure an index that has it (repositories of eu.brain.iot.bis)");
        }
        List<BehaviourResource> allowed = request.operator ? candidates
                : candidates.stream().filter(c -> !ledger.isBlocked(c.symbolicName())).toList();
        if (allowed.isEmpty()) {
            String name = candidates.get(0).symbolicName();
            return failed(Problem.REMOVED_BY_OPERATOR, name + " was removed or stopped by an operator ("
                    + ledger.blocked().get(name) + "), so it is not installed or started automatically; 'bis:allow "
                    + name + "' or 'bis:install " + name + "' in the shell brings it back");
        }
        BehaviourResource chosen = allowed.get(0);
        String reason = request.reason == null || request.reason.isBlank() ? "requested" : request.reason;
        synchronized (this) {
            if (closed) {
                return failed(Problem.CLOSED, "the Bundle Installer is stopping");
            }
            Promise<InstalledBehaviour> running = inflight.get(chosen.symbolicName());
            if (running != null) {
                return running;
            }
            Deferred<InstalledBehaviour> deferred = promises.deferred();
            inflight.put(chosen.symbolicName(), deferred.getPromise());
            try {
                executor.execute(() -> runInstall(chosen, reason, request.operator, deferred));
            } catch (RejectedExecutionException e) {
                inflight.remove(chosen.symbolicName());
                return failed(Problem.CLOSED, "the Bundle Installer is stopping");
            }
            return deferred.getPromise();
        }
    }

    @Override
    public Promise<InstalledBehaviour> uninstall(String symbolicName, String reason, boolean byOperator) {
        return onInstallerThread("uninstall of " + symbolicName, () -> runUninstall(symbolicName, reason, byOperator));
    }

    /**
     * An operator's stop ({@code bis:stop}): the behaviour's bundle is stopped, and it is not started or installed
     * again by an automatic request until an operator allows it ({@link #allow}) or installs it ({@code bis:install},
     * which starts it at once). A bundle stopped by anything else (a failure, Gogo's {@code stop}) is started again by
     * the next request for it, which the BMS makes when it sees the bundle stop.
     */
    public Promise<InstalledBehaviour> stop(String symbolicName, String reason) {
        return onInstallerThread("stop of " + symbolicName, () -> {
            BehaviourRecord record = ledger.get(symbolicName).orElseThrow(() -> new InstallException(
                    Problem.NOT_INSTALLED, symbolicName + " is not installed by the Bundle Installer ('bis:list' shows"
                            + " what is)"));
            // blocked before its bundle stops: the BMS, which sees it stop, asks for it and is refused
            ledger.block(symbolicName, "stopped-by-operator", reason);
            Bundle own = context.getBundle(record.own().location());
            try {
                if (own != null) {
                    own.stop();
                }
            } catch (BundleException e) {
                throw new InstallException(Problem.START_FAILED, symbolicName + " (bundle " + own.getBundleId()
                        + ") failed to stop: " + e.getMessage(), e);
            }
            info.accept("stopped " + symbolicName + " " + record.version() + " (" + reason + ")");
            return dto(record);
        });
    }

    /** @return when and why an installed behaviour was last started again, and how often, or empty */
    public java.util.Optional<Restart> lastRestart(String symbolicName) {
        return ledger.lastRestart(symbolicName);
    }

    /** One step run on the installer's thread, answered through a promise. */
    private interface Step {
        InstalledBehaviour run() throws InstallException, InterruptedException;
    }

    private Promise<InstalledBehaviour> onInstallerThread(String what, Step step) {
        Deferred<InstalledBehaviour> deferred = promises.deferred();
        try {
            executor.execute(() -> {
                try {
                    deferred.resolve(step.run());
                } catch (InstallException e) {
                    deferred.fail(e);
                } catch (InterruptedException e) {
                    deferred.fail(new InstallException(Problem.CLOSED, "the Bundle Installer is stopping"));
                } catch (RuntimeException e) {
                    warn.accept(what + " failed: " + e);
                    deferred.fail(new InstallException(Problem.NOT_INSTALLED, what + " failed: " + e, e));
                }
            });
        } catch (RejectedExecutionException e) {
            return failed(Problem.CLOSED, "the Bundle Installer is stopping");
        }
        return deferred.getPromise();
    }

    @Override
    public void allow(String symbolicName) {
        ledger.allow(symbolicName, "allowed by an operator");
    }

    @Override
    public List<InstalledBehaviour> installed() {
        return ledger.behaviours().stream().map(this::dto).toList();
    }

    /** @return the operator's removals: symbolic name to reason */
    public Map<String, String> blocked() {
        return ledger.blocked();
    }

    /** @return why a journal entry could not be installed again, or null */
    public String restoreProblem(String symbolicName) {
        return restoreProblems.get(symbolicName);
    }

    /** Journal entries not installed again (yet) since the start. */
    public List<BehaviourRecord> pending() {
        return ledger.pending();
    }

    /**
     * Installs again, re-verified, what the journal lists; a behaviour whose bundles are all still in the framework
     * (the installer restarted, not the node) is taken back and started if stopped. Runs on the installer's thread.
     */
    public Promise<Void> restore() {
        Deferred<Void> done = promises.deferred();
        executor.execute(() -> {
            restorePending();
            restored = true;
            done.resolve(null);
        });
        return done.getPromise();
    }

    /**
     * Tries the journal entries that are not back again (called when an index was read anew: the version they need
     * may be offered now, or an unreachable repository answered). Does nothing before {@link #restore()} ran.
     */
    public void retryPending() {
        if (restored && !ledger.pending().isEmpty()) {
            try {
                executor.execute(this::restorePending);
            } catch (RejectedExecutionException e) {
                // stopping
            }
        }
    }

    private void restorePending() {
        for (BehaviourRecord r : ledger.pending()) {
            try {
                restore(r);
                restoreProblems.remove(r.symbolicName());
            } catch (InstallException e) {
                if (!e.getMessage().equals(restoreProblems.put(r.symbolicName(), e.getMessage()))) {
                    warn.accept("the journal lists " + r.symbolicName() + " " + r.version() + " (installed because: "
                            + r.reason() + "), which could not be installed again: " + e.getMessage()
                            + "; it stays in the journal and is tried again when an index changes and at the next"
                            + " start");
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return;
            } catch (RuntimeException e) {
                warn.accept("restoring " + r.symbolicName() + " from the journal failed: " + e);
            }
        }
    }

    public void close() {
        synchronized (this) {
            closed = true;
        }
        executor.shutdownNow();
    }

    private void restore(BehaviourRecord r) throws InstallException, InterruptedException {
        List<Bundle> present = new ArrayList<>();
        for (BundleFact f : r.bundles()) {
            Bundle b = context.getBundle(f.location());
            if (b != null && b.getState() != Bundle.UNINSTALLED) {
                present.add(b);
            }
        }
        boolean blocked = ledger.isBlocked(r.symbolicName());
        if (present.size() == r.bundles().size()) {
            ledger.adopt(r);
            if (blocked) { // stopped by an operator: it stays stopped
                info.accept("journal: " + r.symbolicName() + " " + r.version() + " is still installed, taken back;"
                        + " not started, an operator stopped it");
                return;
            }
            String was = Restarter.stateForPeople(present.get(0));
            if (restarter.ensureActive(r, present.get(0))) {
                ledger.restarted(r, "started again when the installer took it back from its journal (its bundle was "
                        + was + ")", System.currentTimeMillis());
            }
            info.accept("journal: " + r.symbolicName() + " " + r.version() + " is still installed, taken back");
            return;
        }
        if (blocked) {
            throw new InstallException(Problem.REMOVED_BY_OPERATOR, "an operator stopped it ("
                    + ledger.blocked().get(r.symbolicName()) + "); 'bis:install " + r.symbolicName()
                    + "' installs and starts it again");
        }
        List<BehaviourResource> offered = policy.byName(repositories.resources(), r.symbolicName(),
                "[" + r.version() + "," + r.version() + "]");
        if (offered.isEmpty()) {
            throw new InstallException(Problem.NOT_FOUND, "no index in use offers " + r.symbolicName() + " "
                    + r.version() + " now (indexes: " + indexes() + ")");
        }
        BehaviourRecord installed = installNew(offered.get(0), "journal: " + r.reason(), r.installedAt());
        info.accept("journal: " + installed.symbolicName() + " " + installed.version() + " installed again");
    }

    private void runInstall(BehaviourResource chosen, String reason, boolean operator,
            Deferred<InstalledBehaviour> deferred) {
        try {
            if (operator) {
                ledger.allow(chosen.symbolicName(), "installed by an operator");
            }
            BehaviourRecord record = ledger.get(chosen.symbolicName()).orElse(null);
            if (record != null) {
                Bundle own = context.getBundle(record.own().location());
                if (own != null && own.getState() != Bundle.UNINSTALLED) {
                    String was = Restarter.stateForPeople(own);
                    if (restarter.ensureActive(record, own)) {
                        ledger.restarted(record, "started again (its bundle was " + was + "): " + reason,
                                System.currentTimeMillis());
                    }
                    done(chosen, deferred, record);
                    return;
                }
                warn.accept(record.symbolicName() + " was uninstalled behind the installer's back; installing it"
                        + " again");
                removeBundles(record);
                ledger.remove(record.symbolicName(), "vanished", "its bundle was uninstalled by someone else");
                reason = "installed again (its bundle had been uninstalled by someone else, not with bis:uninstall): "
                        + reason;
            }
            for (Bundle b : context.getBundles()) {
                if (chosen.symbolicName().equals(b.getSymbolicName())) {
                    throw new InstallException(Problem.START_FAILED, chosen.symbolicName() + " " + b.getVersion()
                            + " is already in the framework (bundle " + b.getBundleId() + ", " + b.getLocation()
                            + ") but was not installed by the Bundle Installer: start it with 'start " + b.getBundleId()
                            + "', or uninstall it and let the installer manage it");
                }
            }
            done(chosen, deferred, installNew(chosen, reason, System.currentTimeMillis()));
        } catch (InstallException e) {
            warn.accept("install of " + chosen + " failed: " + e.getMessage());
            fail(chosen, deferred, e);
        } catch (InterruptedException e) {
            fail(chosen, deferred, new InstallException(Problem.CLOSED, "the Bundle Installer stopped during the"
                    + " install of " + chosen));
        } catch (RuntimeException e) {
            warn.accept("install of " + chosen + " failed unexpectedly: " + e);
            fail(chosen, deferred, new InstallException(Problem.START_FAILED, "install of " + chosen
                    + " failed unexpectedly: " + e, e));
        }
    }

    private BehaviourRecord installNew(BehaviourResource chosen, String reason, long installedAt)
            throws InstallException, InterruptedException {
        Transaction.Result result = transaction.run(chosen);
        List<BundleFact> facts = new ArrayList<>();
        for (Transaction.Installed i : result.installed()) {
            BundleFact fact = new BundleFact(i.facts().symbolicName(), i.facts().version().toString(),
                    i.facts().sha256(), i.bundle().getLocation());
            if (i.bundle() == result.own()) {
                facts.add(0, fact);
            } else {
                facts.add(fact);
            }
        }
        for (Bundle b : result.reused()) {
            ledger.bundle(b.getLocation()).filter(f -> !facts.contains(f)).ifPresent(facts::add);
        }
        BehaviourRecord record = new BehaviourRecord(chosen.symbolicName(), chosen.version().toString(),
                chosen.consumed(), chosen.repository().toString(), installedAt, reason, facts);
        ledger.put(record, "installed");
        info.accept("installed " + chosen + " from " + chosen.repository() + " with " + (facts.size() - 1)
                + " dependencies (" + reason + ")");
        return record;
    }

    private InstalledBehaviour runUninstall(String symbolicName, String reason, boolean byOperator)
            throws InstallException, InterruptedException {
        BehaviourRecord record = ledger.get(symbolicName).orElse(null);
        if (byOperator) {
            ledger.block(symbolicName, "removed-by-operator", reason == null ? "removed by an operator" : reason);
        }
        if (record == null) {
            if (byOperator) {
                return notInstalled(symbolicName);
            }
            throw new InstallException(Problem.NOT_INSTALLED, symbolicName + " is not installed by the Bundle"
                    + " Installer ('bis:list' shows what is)");
        }
        InstalledBehaviour dto = dto(record);
        // off the list first: whoever sees its bundle's UNINSTALLED event and then asks installed() (the BMS, which
        // brings back a behaviour uninstalled outside the installer) finds it gone by the installer's own hand.
        // removeBundles counts the other users of each bundle, which this removal does not change.
        ledger.remove(symbolicName, byOperator ? "uninstalled-by-operator" : "uninstalled", reason);
        removeBundles(record);
        dto.state = "UNINSTALLED";
        info.accept("uninstalled " + symbolicName + " " + record.version() + " (" + reason + ")");
        return dto;
    }

    /** Uninstalls the behaviour's bundle and those of its bundles no other installed behaviour lists. */
    private void removeBundles(BehaviourRecord record) throws InterruptedException {
        List<Bundle> remove = new ArrayList<>();
        for (BundleFact f : record.bundles()) {
            Bundle b = context.getBundle(f.location());
            if (b != null && ledger.otherUsers(f.location(), record.symbolicName()) == 0) {
                remove.add(b);
            }
        }
        java.util.Collections.reverse(remove); // rollBack reverses again: the behaviour goes first
        transaction.rollBack(remove);
    }

    private void done(BehaviourResource chosen, Deferred<InstalledBehaviour> deferred, BehaviourRecord record) {
        synchronized (this) {
            inflight.remove(chosen.symbolicName());
        }
        deferred.resolve(dto(record));
    }

    private void fail(BehaviourResource chosen, Deferred<InstalledBehaviour> deferred, InstallException e) {
        synchronized (this) {
            inflight.remove(chosen.symbolicName());
        }
        deferred.fail(e);
    }

    private InstalledBehaviour notInstalled(String symbolicName) {
        InstalledBehaviour dto = new InstalledBehaviour();
        dto.symbolicName = symbolicName;
        dto.state = "UNINSTALLED";
        dto.bundles = List.of();
        dto.consumed = List.of();
        return dto;
    }

    private InstalledBehaviour dto(BehaviourRecord r) {
        return Dtos.behaviour(r, context, ledger);
    }

    private String indexes() {
        return repositories.status().stream().map(s -> s.url() + " (" + s.resources() + " resources)").toList()
                .toString();
    }

    private <T> Promise<T> failed(Problem problem, String message) {
        return promises.failed(new InstallException(problem, message));
    }
}
