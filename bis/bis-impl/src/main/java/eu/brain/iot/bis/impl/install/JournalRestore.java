package eu.brain.iot.bis.impl.install;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.RejectedExecutionException;
import java.util.function.Consumer;
import java.util.function.Supplier;

import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.osgi.util.promise.Deferred;
import org.osgi.util.promise.Promise;
import org.osgi.util.promise.PromiseFactory;

import eu.brain.iot.bis.api.InstallException;
import eu.brain.iot.bis.api.InstallException.Problem;
import eu.brain.iot.bis.api.InstalledBehaviour;
import eu.brain.iot.bis.impl.journal.BehaviourRecord;
import eu.brain.iot.bis.impl.journal.BundleFact;
import eu.brain.iot.bis.impl.repo.BehaviourResource;
import eu.brain.iot.bis.impl.repo.Errors;
import eu.brain.iot.bis.impl.repo.Repositories;

/**
 * Brings back what the journal lists: at the installer's start ({@link #restore()}) and whenever an index changes
 * ({@link #retryPending()}). An entry whose bundles are still in the framework is taken back; any other is installed
 * again, re-verified, as an install of the installer's (downloads off the installer's thread). An entry that cannot
 * come back keeps its reason in {@link #problem}, stays in the journal, and is tried again.
 * <p>
 * Threads: the work runs on the installer's thread; {@link #restoreProblems} is a concurrent map (read by Gogo);
 * {@link #restored} is volatile (read by the index readers' threads).
 */
final class JournalRestore {

    static final String JOURNAL_PREFIX = "journal: ";

    /** Starts an install of the installer's (or joins the one under way for that behaviour). */
    interface Installs {
        Promise<InstalledBehaviour> start(BehaviourResource chosen, String reason, long installedAt);
    }

    private final BundleContext context;
    private final Ledger ledger;
    private final Restarter restarter;
    private final ChoicePolicy policy;
    private final Repositories repositories;
    private final ExecutorService executor;
    private final PromiseFactory promises;
    private final Installs installs;
    private final Supplier<String> indexes;
    private final Consumer<String> warn;
    private final Consumer<String> info;
    /** Why a journal entry is not back. */
    private final Map<String, String> restoreProblems = new ConcurrentHashMap<>();
    /** Set once the start's restore ran. */
    private volatile boolean restored;

    JournalRestore(BundleContext context, Ledger ledger, Restarter restarter, ChoicePolicy policy,
            Repositories repositories, ExecutorService executor, PromiseFactory promises, Installs installs,
            Supplier<String> indexes, Consumer<String> warn, Consumer<String> info) {
        this.context = context;
        this.ledger = ledger;
        this.restarter = restarter;
        this.policy = policy;
        this.repositories = repositories;
        this.executor = executor;
        this.promises = promises;
        this.installs = installs;
        this.indexes = indexes;
        this.warn = warn;
        this.info = info;
    }

    /** @return why the journal entry could not be installed again, or null */
    String problem(String symbolicName) {
        return restoreProblems.get(symbolicName);
    }

    /**
     * Installs again, re-verified, what the journal lists; a behaviour whose bundles are all still in the framework
     * (the installer restarted, not the node) is taken back and started if stopped. The promise resolves once every
     * entry is back or has failed (then {@link #restoreProblem} says why, and it is tried again when an index changes).
     */
    Promise<Void> restore() {
        Deferred<Void> done = promises.deferred();
        try {
            executor.execute(() -> {
                List<Promise<InstalledBehaviour>> started = restorePending();
                restored = true;
                promises.all(started).onResolve(() -> done.resolve(null));
            });
        } catch (RejectedExecutionException e) {
            done.resolve(null);
        }
        return done.getPromise();
    }

    /**
     * Tries the journal entries that are not back again (called when an index was read anew: the version they need
     * may be offered now, or an unreachable repository answered). Does nothing before {@link #restore()} ran.
     */
    void retryPending() {
        if (restored && !ledger.pending().isEmpty()) {
            try {
                executor.execute(this::restorePending);
            } catch (RejectedExecutionException e) {
                // stopping
            }
        }
    }

    /** Runs on the installer's thread; the entries to install again are started as jobs, whose promises it returns. */
    private List<Promise<InstalledBehaviour>> restorePending() {
        List<Promise<InstalledBehaviour>> started = new ArrayList<>();
        for (BehaviourRecord r : ledger.pending()) {
            try {
                Promise<InstalledBehaviour> install = restoreOne(r);
                if (install == null) {
                    restoreProblems.remove(r.symbolicName());
                } else {
                    started.add(install.onSuccess(b -> {
                        restoreProblems.remove(r.symbolicName());
                        info.accept("journal: " + b.symbolicName + " " + b.version + " installed again");
                    }).onFailure(e -> restoreFailed(r, e)));
                }
            } catch (InstallException e) {
                restoreFailed(r, e);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                break;
            } catch (RuntimeException e) {
                warn.accept("restoring " + r.symbolicName() + " from the journal failed: " + Errors.describe(e));
            }
        }
        return started;
    }

    private void restoreFailed(BehaviourRecord r, Throwable e) {
        String message = e instanceof InstallException ? e.getMessage() : Errors.describe(e);
        if (!message.equals(restoreProblems.put(r.symbolicName(), message))) {
            warn.accept("the journal lists " + r.symbolicName() + " " + r.version() + " (installed because: "
                    + r.reason() + "), which could not be installed again: " + message + "; it stays in the journal"
                    + " and is tried again when an index changes and at the next start");
        }
    }

    /** @return an install under way for the entry, or null when it was taken back as it is */
    private Promise<InstalledBehaviour> restoreOne(BehaviourRecord r) throws InstallException, InterruptedException {
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
                return null;
            }
            String was = Restarter.stateForPeople(present.get(0));
            if (restarter.ensureActive(r, present.get(0))) {
                ledger.restarted(r, "started again when the installer took it back from its journal (its bundle was "
                        + was + ")", System.currentTimeMillis());
            }
            info.accept("journal: " + r.symbolicName() + " " + r.version() + " is still installed, taken back");
            return null;
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
                    + r.version() + " now (indexes: " + indexes.get() + ")");
        }
        return installs.start(offered.get(0), JOURNAL_PREFIX + withoutJournalPrefix(r.reason()), r.installedAt());
    }

    /** A reason as first given: an entry installed again from the journal says so once, not once per restart. */
    static String withoutJournalPrefix(String reason) {
        String original = reason == null ? "" : reason;
        while (original.startsWith(JOURNAL_PREFIX)) {
            original = original.substring(JOURNAL_PREFIX.length());
        }
        return original;
    }

}
