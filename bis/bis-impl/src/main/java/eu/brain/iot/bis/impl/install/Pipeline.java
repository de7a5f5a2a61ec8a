package eu.brain.iot.bis.impl.install;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.RejectedExecutionException;
import java.util.function.Consumer;
import java.util.function.Function;

import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;

import eu.brain.iot.bis.api.InstallException;
import eu.brain.iot.bis.api.InstallException.Problem;
import eu.brain.iot.bis.api.InstalledBehaviour;
import eu.brain.iot.bis.impl.journal.BehaviourRecord;
import eu.brain.iot.bis.impl.journal.BundleFact;
import eu.brain.iot.bis.impl.repo.BehaviourResource;
import eu.brain.iot.bis.impl.repo.Errors;

/**
 * The steps of one install ({@link Job}): checks and resolution on the installer's thread, downloads on a download
 * thread, then back on the installer's thread to resolve again and install from the verified files; the job's promise
 * resolves or fails at the end, and its files are deleted.
 * <p>
 * Threads: {@link #runInstall} and {@link #proceed} run on the installer's thread ({@code executor}), the downloads on
 * {@code downloader}; a job is on one of them at a time (handed over through the executors).
 */
final class Pipeline {

    /** How often an install resolves again after its downloads before it gives up (the framework kept changing). */
    private static final int MAX_ROUNDS = 3;

    private final BundleContext context;
    private final Ledger ledger;
    private final Transaction transaction;
    private final Restarter restarter;
    private final Downloads downloads;
    private final ExecutorService executor;
    private final ExecutorService downloader;
    private final Consumer<Job> finished;
    private final Function<BehaviourRecord, InstalledBehaviour> dto;
    private final Consumer<String> warn;
    private final Consumer<String> info;

    Pipeline(BundleContext context, Ledger ledger, Transaction transaction, Restarter restarter, Downloads downloads,
            ExecutorService executor, ExecutorService downloader, Consumer<Job> finished,
            Function<BehaviourRecord, InstalledBehaviour> dto, Consumer<String> warn, Consumer<String> info) {
        this.context = context;
        this.ledger = ledger;
        this.transaction = transaction;
        this.restarter = restarter;
        this.downloads = downloads;
        this.executor = executor;
        this.downloader = downloader;
        this.finished = finished;
        this.dto = dto;
        this.warn = warn;
        this.info = info;
    }

    /** The first step of an install request, on the installer's thread. */
    void runInstall(Job job) {
        BehaviourResource chosen = job.chosen;
        try {
            if (job.operator) {
                Installer.journaled(() -> ledger.allow(chosen.symbolicName(), "installed by an operator"), chosen.symbolicName()
                        + " was not installed");
            }
            BehaviourRecord record = ledger.get(chosen.symbolicName()).orElse(null);
            if (record != null) {
                Bundle own = context.getBundle(record.own().location());
                if (own != null && own.getState() != Bundle.UNINSTALLED) {
                    String was = Restarter.stateForPeople(own);
                    if (restarter.ensureActive(record, own)) {
                        ledger.restarted(record, "started again (its bundle was " + was + "): " + job.reason,
                                System.currentTimeMillis());
                    }
                    done(job, record);
                    return;
                }
                warn.accept(record.symbolicName() + " was uninstalled behind the installer's back; installing it"
                        + " again");
                removeBundles(record);
                Installer.journaled(() -> ledger.remove(record.symbolicName(), "vanished", "its bundle was uninstalled by"
                        + " someone else"), chosen.symbolicName() + " was not installed again");
                job.vanished = true;
            }
            for (Bundle b : context.getBundles()) {
                if (chosen.symbolicName().equals(b.getSymbolicName())) {
                    throw new InstallException(Problem.START_FAILED, chosen.symbolicName() + " " + b.getVersion()
                            + " is already in the framework (bundle " + b.getBundleId() + ", " + b.getLocation()
                            + ") but was not installed by the Bundle Installer: start it with 'start " + b.getBundleId()
                            + "', or uninstall it and let the installer manage it");
                }
            }
            proceed(job);
        } catch (InstallException e) {
            fail(job, e);
        } catch (InterruptedException e) {
            fail(job, new InstallException(Problem.CLOSED, "the Bundle Installer stopped during the install of "
                    + chosen));
        } catch (RuntimeException e) {
            fail(job, new InstallException(Problem.START_FAILED, "install of " + chosen + " failed unexpectedly: "
                    + Errors.describe(e), e));
        }
    }

    /**
     * On the installer's thread: resolves; hands what is not downloaded yet to a download thread, which brings the
     * job back here when done; or, with everything downloaded, installs and starts.
     */
    void proceed(Job job) {
        try {
            Transaction.Plan plan = transaction.plan(job.chosen);
            List<BehaviourResource> missing = plan.order().stream()
                    .filter(r -> !job.files.containsKey(Downloads.key(r))).toList();
            if (missing.isEmpty()) {
                done(job, installNew(job, plan));
                return;
            }
            if (job.rounds++ >= MAX_ROUNDS) {
                throw new InstallException(Problem.UNRESOLVED, job.chosen + " needed other bundles after each of "
                        + MAX_ROUNDS + " downloads (the framework or the indexes kept changing); try again");
            }
            downloader.execute(() -> download(job, missing));
        } catch (InstallException e) {
            fail(job, e);
        } catch (InterruptedException e) {
            fail(job, new InstallException(Problem.CLOSED, "the Bundle Installer stopped during the install of "
                    + job.chosen));
        } catch (RejectedExecutionException e) {
            fail(job, new InstallException(Problem.CLOSED, "the Bundle Installer is stopping"));
        } catch (RuntimeException e) {
            fail(job, new InstallException(Problem.START_FAILED, "install of " + job.chosen + " failed unexpectedly: "
                    + Errors.describe(e), e));
        }
    }

    /** On a download thread: fetches and verifies, then hands the job back to the installer's thread. */
    private void download(Job job, List<BehaviourResource> missing) {
        try {
            downloads.fetch(job.chosen, missing, job.files);
            executor.execute(() -> proceed(job));
        } catch (InstallException e) {
            fail(job, e);
        } catch (InterruptedException e) {
            fail(job, new InstallException(Problem.CLOSED, "the Bundle Installer stopped during the download for "
                    + job.chosen));
        } catch (RejectedExecutionException e) {
            fail(job, new InstallException(Problem.CLOSED, "the Bundle Installer is stopping"));
        } catch (RuntimeException e) {
            fail(job, new InstallException(Problem.DOWNLOAD_FAILED, "download for " + job.chosen + " failed"
                    + " unexpectedly: " + Errors.describe(e), e));
        }
    }

    private BehaviourRecord installNew(Job job, Transaction.Plan plan) throws InstallException, InterruptedException {
        BehaviourResource chosen = job.chosen;
        Transaction.Result result = transaction.apply(plan, job.files);
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
        String reason = job.vanished ? "installed again (its bundle had been uninstalled by someone else, not with"
                + " bis:uninstall): " + job.reason : job.reason;
        BehaviourRecord record = new BehaviourRecord(chosen.symbolicName(), chosen.version().toString(),
                chosen.consumed(), chosen.repository().toString(), job.installedAt, reason, facts);
        try {
            ledger.put(record, "installed");
        } catch (java.io.IOException e) {
            transaction.rollBack(result.installed().stream().map(Transaction.Installed::bundle).toList());
            throw new InstallException(Problem.JOURNAL_FAILED, e.getMessage() + "; " + chosen + " was uninstalled"
                    + " again, so that the node stays as the journal says", e);
        }
        info.accept("installed " + chosen + " from " + chosen.repository() + " with " + (facts.size() - 1)
                + " dependencies (" + reason + ")");
        return record;
    }

    /** Uninstalls the behaviour's bundle and those of its bundles no other installed behaviour lists. */
    void removeBundles(BehaviourRecord record) throws InterruptedException {
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

    private void done(Job job, BehaviourRecord record) {
        finished(job);
        job.deferred.resolve(dto(record));
    }

    private void fail(Job job, InstallException e) {
        if (e.problem() != Problem.CLOSED) {
            warn.accept("install of " + job.chosen + " failed: " + e.getMessage());
        }
        finished(job);
        job.deferred.fail(e);
    }

    private void finished(Job job) {
        finished.accept(job);
        job.files.values().forEach(Downloads::delete);
    }

    private InstalledBehaviour dto(BehaviourRecord record) {
        return dto.apply(record);
    }
}
