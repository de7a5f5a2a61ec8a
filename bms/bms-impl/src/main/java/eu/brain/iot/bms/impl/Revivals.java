package eu.brain.iot.bms.impl;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.BiConsumer;
import java.util.function.BooleanSupplier;
import java.util.function.Supplier;

import org.osgi.service.log.Logger;
import org.osgi.util.promise.Promise;

import eu.brain.iot.bis.api.BundleInstaller;
import eu.brain.iot.bis.api.InstallException;
import eu.brain.iot.bis.api.InstallException.Problem;
import eu.brain.iot.bis.api.InstalledBehaviour;

/**
 * Brings back a behaviour the installer installed whose bundle stopped or was uninstalled outside the installer (a
 * failure, Gogo's {@code stop} or {@code uninstall}, {@code Bundle.stop()}), without waiting for an event it alone
 * consumes: such an event may never come (the warehouse's robots queued at a door only the stopped robot behaviour
 * opens). It asks the installer for the behaviour as an automatic request, which starts the same bundle again (its
 * dependencies first) or installs it again when it is gone, and records it as the event path does
 * ({@code RESTARTED}, {@code REINSTALLED} in the history, the installer's journal).
 * <p>
 * What it leaves alone, and how it tells:
 * <ul>
 * <li>a bundle active again when {@code restart.grace.ms} has passed (a refresh, an update): it looks again after the
 * grace, on the installer's list ({@link BundleInstaller#installed()});</li>
 * <li>a bundle the installer did not install (the node's own, one an operator installed by hand): not on its list;
 * </li>
 * <li>the installer's own removals ({@code bis:uninstall}, its uninstall, a rollback): it takes a behaviour off its
 * list before it uninstalls the bundles, and a rollback's bundles were never on it;</li>
 * <li>an operator's {@code bis:stop} (or {@code bis:uninstall}): the installer refuses automatic requests for it
 * ({@code REMOVED_BY_OPERATOR}), which this class takes as the operator's word: no retry, no alert, a log line;</li>
 * <li>anything while the framework shuts down.</li>
 * </ul>
 * Not a restart loop: a failed attempt is retried with the event path's backoff ({@code retry.initial.ms} doubling up
 * to {@code retry.max.ms}), each failure alerted ({@code BehaviourInstallFailed} with no event type), until
 * {@code install.deadline.ms} from the stop; then it gives up (a final alert) and leaves the behaviour alone for
 * {@code negative.cache.ms}. A behaviour that goes away again within {@code install.deadline.ms} of being brought back
 * continues the same episode: the next attempt waits the backoff, and the deadline still counts from the first stop.
 * While an attempt is made, the stops its own failures cause are part of it. When events of the behaviour's types
 * are held meanwhile, they join its request ({@link InstallJobs}); when the event path asks first, this class steps
 * back and the event path's retries and alerts apply.
 * <p>
 * Threads: every method runs on the BMS's thread ({@link Scheduler}); the framework's bundle events only queue
 * {@link #wentAway} there ({@link BundleWatch}). {@link #revivals} belongs to that thread; it holds at most one
 * entry per behaviour the installer installed.
 */
final class Revivals {

    private static final String RESTARTED = "RESTARTED";
    private static final String REINSTALLED = "REINSTALLED";

    /** Where the BMS stands with one behaviour's bundle. Immutable: replaced as a whole. */
    private sealed interface Revival {
    }

    /** Its bundle went away at {@code since} (or the episode that started then goes on); asked at the grace's end. */
    private record Noticed(long since, int attempt) implements Revival {
    }

    /** A request is in flight. */
    private record Asking(long since, int attempt, long job, Target target) implements Revival {
    }

    /** The last attempt failed; the next is at {@code nextRetry}. */
    private record Waiting(long since, int attempt, Target target, long nextRetry) implements Revival {
    }

    /** Brought back; going away again before {@code since + install.deadline.ms} continues the episode. */
    private record Back(long since, int attempt) implements Revival {
    }

    /** Given up: left alone until {@code until}, whatever its bundle does (the event path's failed starts stop it). */
    private record Resting(long until) implements Revival {
    }

    /** What is asked for: the kind of request, and the behaviour's version and types. */
    private record Target(String kind, String version, List<String> consumed) {
    }

    private final BundleInstaller installer;
    private final InstallJobs jobs;
    private final Scheduler scheduler;
    private final Alerts alerts;
    private final Logger log;
    private final ManagerCountersImpl counters;
    private final History history;
    private final Supplier<Settings> settings;
    private final BooleanSupplier frameworkStopping;
    private final BiConsumer<InstallJob, Promise<InstalledBehaviour>> answered;
    private final Map<String, Revival> revivals = new HashMap<>();

    /**
     * @param settings the BMS's settings now (they change in place)
     * @param answered where the installer's answers to this class's requests go first: {@link BehaviourManager}, as
     *        event types may have joined them; it calls {@link #answered} back
     */
    Revivals(BundleInstaller installer, InstallJobs jobs, Scheduler scheduler, Alerts alerts, Logger log,
            ManagerCountersImpl counters, History history, Supplier<Settings> settings,
            BooleanSupplier frameworkStopping, BiConsumer<InstallJob, Promise<InstalledBehaviour>> answered) {
        this.installer = installer;
        this.jobs = jobs;
        this.scheduler = scheduler;
        this.alerts = alerts;
        this.log = log;
        this.counters = counters;
        this.history = history;
        this.settings = settings;
        this.frameworkStopping = frameworkStopping;
        this.answered = answered;
    }

    /** A bundle stopped or was uninstalled: if it is a behaviour the installer installed, look again after a grace. */
    void wentAway(String symbolicName, long bundleId) {
        if (symbolicName == null || frameworkStopping.getAsBoolean()) {
            return;
        }
        long now = scheduler.now();
        Revival current = revivals.get(symbolicName);
        if (current instanceof Noticed || current instanceof Asking || current instanceof Waiting) {
            return; // on it already: a failed start of ours stops the bundle again, an uninstall stops it first
        }
        if (current instanceof Resting r && now < r.until()) {
            return;
        }
        InstalledBehaviour listed = listed(symbolicName);
        if (listed == null || (listed.bundleId >= 0 && listed.bundleId != bundleId)) {
            revivals.remove(symbolicName); // not the installer's (or not that bundle), or the installer removed it
            return;
        }
        Settings s = settings.get();
        long delay = s.restartGraceMs();
        Noticed noticed = new Noticed(now, 1);
        if (current instanceof Back back && now < back.since() + s.installDeadlineMs()) {
            // back, and gone again soon after: the same episode, the next attempt after the backoff
            delay = Math.max(delay, s.backoff(back.attempt()));
            noticed = new Noticed(back.since(), back.attempt() + 1);
            if (now + delay >= back.since() + s.installDeadlineMs()) {
                giveUp(symbolicName, listed.symbolicName + " " + listed.version, back.since(), back.attempt(),
                        "TIMEOUT", "its bundle kept going away after it was brought back (brought back "
                                + back.attempt() + " times in the " + (now - back.since()) + " ms since it first went"
                                + " away; install.deadline.ms " + s.installDeadlineMs() + ")");
                return;
            }
        }
        Noticed n = noticed;
        revivals.put(symbolicName, n);
        scheduler.schedule(() -> {
            if (revivals.get(symbolicName) == n) {
                ask(symbolicName, n.since(), n.attempt(), null);
            }
        }, delay);
    }

    /**
     * Asks the installer to bring it back, unless it is not to be: the framework stops, the event path asks already,
     * it is active again, or the installer no longer lists it. {@code retrying}: the previous attempt's target (the
     * installer no longer lists a behaviour whose reinstall failed, yet it is to be installed again), or null.
     */
    private void ask(String symbolicName, long since, int attempt, Target retrying) {
        if (frameworkStopping.getAsBoolean() || jobs.inFlight(symbolicName) != null) {
            revivals.remove(symbolicName); // shutting down; or events asked for it: the event path brings it back
            return;
        }
        InstalledBehaviour listed = listed(symbolicName);
        Target target;
        if (listed != null && "ACTIVE".equals(listed.state)) {
            revivals.remove(symbolicName); // active again: a refresh, an update, someone started it
            return;
        } else if (listed != null) {
            target = new Target("UNINSTALLED".equals(listed.state) ? REINSTALLED : RESTARTED, listed.version,
                    listed.consumed == null ? List.of() : listed.consumed);
        } else if (retrying != null && retrying.kind().equals(REINSTALLED)) {
            target = retrying;
        } else {
            revivals.remove(symbolicName); // the installer removed it meanwhile
            return;
        }
        String reason = target.kind().equals(RESTARTED)
                ? "its bundle was stopped outside the installer (not with bis:stop: a failure, Gogo's stop): started"
                        + " again without waiting for an event (Behaviour Management Service)"
                : "its bundle was uninstalled outside the installer (not with bis:uninstall): installed again"
                        + " without waiting for an event (Behaviour Management Service)";
        InstallJob job = jobs.start(symbolicName, target.version(), null, target.consumed(), target.kind(), reason,
                true, answered);
        revivals.put(symbolicName, new Asking(since, attempt, job.id(), target));
    }

    /**
     * The installer answered a request of this class. {@code eventsWaiting}: event types joined it, and the event path
     * records the outcome and retries for them; this class only remembers a success.
     */
    void answered(InstallJob job, Promise<InstalledBehaviour> answer, boolean eventsWaiting) {
        String name = job.symbolicName();
        if (!(revivals.get(name) instanceof Asking a) || a.job() != job.id()) {
            return;
        }
        long now = scheduler.now();
        Throwable failure = Answers.failure(answer);
        if (failure == null) {
            revivals.put(name, new Back(a.since(), a.attempt()));
            if (!eventsWaiting) {
                InstalledBehaviour done = Answers.value(answer);
                counters.installs.increment();
                history.add(History.entry(now, job.kind(), List.of(), job.behaviour(), now - a.since(), a.attempt(), 0,
                        job.reason()));
                alerts.installed(List.of(), done.symbolicName, done.version, done.repository, now - a.since(),
                        a.attempt());
                log.info("{} {} without waiting for an event, {} ms after its bundle went away (attempt {}): {}",
                        job.kind().equals(RESTARTED) ? "Started again" : "Installed again", job.behaviour(),
                        now - a.since(), a.attempt(), job.reason());
            }
            return;
        }
        if (eventsWaiting) {
            revivals.remove(name);
            return;
        }
        Problem problem = failure instanceof InstallException ie ? ie.problem() : Problem.START_FAILED;
        String reason = failure.getMessage() == null ? failure.toString() : failure.getMessage();
        Settings s = settings.get();
        switch (problem) {
        case REMOVED_BY_OPERATOR -> {
            // bis:stop or bis:uninstall: the operator's word; not a failure, nothing to alert. Once an operator lets it
            // run again (bis:install, bis:allow), its next stop outside the installer is a fault again: no rest here
            revivals.remove(name);
            log.info("Not bringing back {}: an operator stopped or removed it ({}); 'bis:install {}' or 'bis:allow {}'"
                    + " does", job.behaviour(), reason, name, name);
        }
        // no longer the installer's, or the installer is stopping: nothing to bring back
        case NOT_INSTALLED, CLOSED -> revivals.remove(name);
        // a tampered bundle, an index that no longer offers it: neither fixes itself
        case HASH_MISMATCH, NOT_FOUND -> {
            counters.installFailures.increment();
            giveUp(name, job.behaviour(), a.since(), a.attempt(), problem.name(), reason);
        }
        default -> {
            counters.installFailures.increment();
            long delay = s.backoff(a.attempt());
            if (now + delay >= a.since() + s.installDeadlineMs()) {
                giveUp(name, job.behaviour(), a.since(), a.attempt(), problem.name(), reason);
                return;
            }
            Waiting w = new Waiting(a.since(), a.attempt(), a.target(), now + delay);
            revivals.put(name, w);
            history.add(History.entry(now, "INSTALL_FAILED", List.of(), job.behaviour(), now - a.since(), a.attempt(),
                    0, problem + ": " + reason));
            alerts.installFailed(null, job.behaviour(), problem.name(), reason, a.attempt(), w.nextRetry(), 0);
            log.warn("Bringing back {} failed (attempt {}, {}): {}. Next attempt in {} ms, giving up {} ms after its"
                    + " bundle went away (install.deadline.ms).", job.behaviour(), a.attempt(), problem, reason, delay,
                    s.installDeadlineMs());
            scheduler.schedule(() -> {
                if (revivals.get(name) == w) {
                    ask(name, w.since(), w.attempt() + 1, w.target());
                }
            }, delay);
        }
        }
    }

    private void giveUp(String name, String behaviour, long since, int attempt, String problem, String reason) {
        long now = scheduler.now();
        Settings s = settings.get();
        revivals.put(name, new Resting(now + s.negativeCacheMs()));
        history.add(History.entry(now, "GAVE_UP", List.of(), behaviour, now - since, attempt, 0, reason));
        alerts.installFailed(null, behaviour, problem, reason, attempt, 0, 0);
        log.error("Gave up bringing back {} after {} attempt(s): {}. Its bundle going away is not acted on for {} ms"
                + " (negative.cache.ms); an event it consumes still asks for it. Fix the behaviour or the repository,"
                + " or bring it back by hand (bis:install).", behaviour, attempt, reason, s.negativeCacheMs());
    }

    private InstalledBehaviour listed(String symbolicName) {
        for (InstalledBehaviour b : installer.installed()) {
            if (symbolicName.equals(b.symbolicName)) {
                return b;
            }
        }
        return null;
    }
}
