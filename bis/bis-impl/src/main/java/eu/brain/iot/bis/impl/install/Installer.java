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
import eu.brain.iot.bis.impl.journal.Journal;
import eu.brain.iot.bis.impl.repo.BehaviourResource;
import eu.brain.iot.bis.impl.repo.Repositories;
import eu.brain.iot.bis.impl.repo.UrlReader;
import eu.brain.iot.eventing.monitoring.api.EventBusStatistics;

/**
 * The local {@link BundleInstaller}. Requests are answered at once with a promise. What changes the framework
 * (resolving, installing, starting, uninstalling) runs one step at a time on the installer's single thread
 * ({@code executor}), so that each step sees the framework as the previous one left it; downloads run apart, on the
 * download threads ({@code downloader}), one install's at a time per thread: an install resolves, hands its downloads
 * over and leaves the installer's thread free, and comes back to it to install what arrived (resolving again, in case
 * another install changed the framework meanwhile). So a slow download holds up its own install only. Requests for a
 * behaviour already being installed get that install's promise.
 * <p>
 * Threads: {@link #inflight} and {@link #closed} are guarded by {@code this}; the {@link Ledger} guards itself; a
 * {@link Job}'s files are a concurrent map handed between the installer's thread and one download thread at a time;
 * everything else is touched only on the installer's thread. Promise callbacks run on the promise factory's callback
 * executor, never on the installer's thread.
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
    private final Downloads downloads;
    private final ExecutorService downloader;
    private final Map<String, Job> inflight = new HashMap<>();
    private boolean closed;
    private final JournalRestore journalRestore;
    private final Pipeline pipeline;


    /** What an install needs besides the framework: where and how it downloads, on which threads it runs. */
    public record Threads(ExecutorService executor, ExecutorService downloader, PromiseFactory promises) {
    }

    /**
     * @param loaded what the journal held at start
     * @param downloadFolder where downloads are kept until installed (the bundle's data area)
     * @param bundleMaxBytes the largest bundle read when its index states no size
     */
    public static Installer create(BundleContext context, Resolver resolver, Repositories repositories,
            UrlReader reader, Journal journal, Journal.State loaded, List<String> prefer, long activationTimeoutMillis,
            Supplier<EventBusStatistics> statistics, Threads threads, java.nio.file.Path downloadFolder,
            long bundleMaxBytes, Consumer<String> error, Consumer<String> warn, Consumer<String> info) {
        Ledger ledger = new Ledger(journal, loaded, error);
        Activation activation = new Activation(context, statistics);
        Transaction transaction = new Transaction(context, resolver, repositories, activation,
                activationTimeoutMillis, warn);
        return new Installer(context, repositories, new ChoicePolicy(prefer), ledger, transaction,
                new Restarter(context, activation, activationTimeoutMillis, info),
                new Downloads(reader, downloadFolder, bundleMaxBytes), threads, warn, info);
    }

    private Installer(BundleContext context, Repositories repositories, ChoicePolicy policy, Ledger ledger,
            Transaction transaction, Restarter restarter, Downloads downloads, Threads threads,
            Consumer<String> warn, Consumer<String> info) {
        this.context = context;
        this.repositories = repositories;
        this.policy = policy;
        this.ledger = ledger;
        this.transaction = transaction;
        this.restarter = restarter;
        this.downloads = downloads;
        this.executor = threads.executor();
        this.downloader = threads.downloader();
        this.promises = threads.promises();
        this.warn = warn;
        this.info = info;
        this.pipeline = new Pipeline(context, ledger, transaction, restarter, downloads, executor, downloader,
                this::finished, this::dto, warn, info);
        this.journalRestore = new JournalRestore(context, ledger, restarter, policy, repositories, executor,
                promises, (chosen, reason, installedAt) -> start(new Job(chosen, reason, installedAt, false,
                        promises.deferred()), pipeline::proceed), this::indexes, warn, info);
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
        return start(new Job(chosen, reason, System.currentTimeMillis(), request.operator, promises.deferred()),
                pipeline::runInstall);
    }

    /** Starts a job on the installer's thread, or answers with the running job of that behaviour. */
    private Promise<InstalledBehaviour> start(Job job, Consumer<Job> first) {
        synchronized (this) {
            if (closed) {
                return failed(Problem.CLOSED, "the Bundle Installer is stopping");
            }
            Job running = inflight.get(job.chosen.symbolicName());
            if (running != null) {
                return running.deferred.getPromise();
            }
            inflight.put(job.chosen.symbolicName(), job);
            try {
                executor.execute(() -> first.accept(job));
            } catch (RejectedExecutionException e) {
                inflight.remove(job.chosen.symbolicName());
                return failed(Problem.CLOSED, "the Bundle Installer is stopping");
            }
            return job.deferred.getPromise();
        }
    }

    @Override
    public List<String> activities() {
        List<String> lines = new ArrayList<>(downloads.activities());
        synchronized (this) {
            for (Job job : inflight.values()) {
                String name = job.chosen.toString();
                if (lines.stream().noneMatch(l -> l.contains(name))) {
                    lines.add("installing " + name + " (resolving, installing or starting; " + job.reason + ")");
                }
            }
        }
        return lines;
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
            journaled(() -> ledger.block(symbolicName, "stopped-by-operator", reason), symbolicName + " was not"
                    + " stopped");
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
        try {
            allowOrFail(symbolicName);
        } catch (InstallException e) {
            warn.accept(e.getMessage());
        }
    }

    /**
     * Lifts an operator's removal, saying when the journal could not record it.
     *
     * @return whether it was removed by an operator
     */
    public boolean allowOrFail(String symbolicName) throws InstallException {
        boolean[] was = new boolean[1];
        journaled(() -> was[0] = ledger.allow(symbolicName, "allowed by an operator"), symbolicName
                + " is still not installed automatically");
        return was[0];
    }

    /** A journal change; a journal that cannot be written fails the step, saying what was not done. */
    interface JournalChange {
        void run() throws java.io.IOException;
    }

    static void journaled(JournalChange change, String consequence) throws InstallException {
        try {
            change.run();
        } catch (java.io.IOException e) {
            throw new InstallException(Problem.JOURNAL_FAILED, e.getMessage() + "; " + consequence, e);
        }
    }

    /** @return the names of the behaviours installed and of those the journal lists that are not back yet */
    public List<String> known() {
        List<String> names = new ArrayList<>();
        ledger.behaviours().forEach(b -> names.add(b.symbolicName()));
        ledger.pending().forEach(b -> names.add(b.symbolicName() + " (journal, not back yet)"));
        return names;
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
        return journalRestore.problem(symbolicName);
    }

    /** Journal entries not installed again (yet) since the start. */
    public List<BehaviourRecord> pending() {
        return ledger.pending();
    }

    /** Whether an index in use offers every journal entry not back yet, in its version. */
    public boolean pendingOffered() {
        List<BehaviourResource> offered = repositories.resources();
        return ledger.pending().stream().allMatch(r -> offered.stream().anyMatch(o -> o.symbolicName()
                .equals(r.symbolicName()) && o.version().toString().equals(r.version())));
    }

    /** @see JournalRestore#restore() */
    public Promise<Void> restore() {
        return journalRestore.restore();
    }

    /** @see JournalRestore#retryPending() */
    public void retryPending() {
        journalRestore.retryPending();
    }

    public void close() {
        synchronized (this) {
            closed = true;
        }
        executor.shutdownNow();
        downloader.shutdownNow();
    }

    private InstalledBehaviour runUninstall(String symbolicName, String reason, boolean byOperator)
            throws InstallException, InterruptedException {
        BehaviourRecord record = ledger.get(symbolicName).orElse(null);
        String why = reason == null ? "removed by an operator" : reason;
        if (record == null) {
            BehaviourRecord entry = ledger.pendingEntry(symbolicName).orElse(null);
            if (entry != null || byOperator) {
                // a journal entry not back yet is forgotten; an operator's removal of one not installed keeps it out
                journaled(() -> {
                    if (byOperator) {
                        ledger.block(symbolicName, "removed-by-operator", why);
                    }
                    if (entry != null) {
                        ledger.remove(symbolicName, "forgotten", why);
                    }
                }, symbolicName + " was not removed");
                return notInstalled(symbolicName);
            }
            throw new InstallException(Problem.NOT_INSTALLED, "nothing is installed under the name " + symbolicName
                    + " (installed: " + (known().isEmpty() ? "none" : String.join(", ", known()))
                    + "; 'bis:list' shows them)");
        }
        InstalledBehaviour dto = dto(record);
        // off the list first: whoever sees its bundle's UNINSTALLED event and then asks installed() (the BMS, which
        // brings back a behaviour uninstalled outside the installer) finds it gone by the installer's own hand.
        // removeBundles counts the other users of each bundle, which this removal does not change. The journal
        // first: when it cannot be written, nothing is uninstalled.
        journaled(() -> {
            if (byOperator) {
                ledger.block(symbolicName, "removed-by-operator", why);
            }
            ledger.remove(symbolicName, byOperator ? "uninstalled-by-operator" : "uninstalled", reason);
        }, symbolicName + " was NOT uninstalled and stays as it was");
        pipeline.removeBundles(record);
        dto.state = "UNINSTALLED";
        info.accept("uninstalled " + symbolicName + " " + record.version() + " (" + reason + ")");
        return dto;
    }

    /** An install ended: no longer under way. */
    private void finished(Job job) {
        synchronized (this) {
            inflight.remove(job.chosen.symbolicName(), job);
        }
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
