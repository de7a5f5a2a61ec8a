package eu.brain.iot.bis.impl.install;

import java.nio.file.Path;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

import org.osgi.util.promise.Deferred;

import eu.brain.iot.bis.api.InstalledBehaviour;
import eu.brain.iot.bis.impl.repo.BehaviourResource;

/**
 * One install under way: what, why, and the verified files downloaded for it so far. Threads: the files are a
 * concurrent map handed between the installer's thread and one download thread at a time; {@link #rounds} and
 * {@link #vanished} are the installer's thread's only.
 */
final class Job {
    final BehaviourResource chosen;
    final String reason;
    final long installedAt;
    final boolean operator;
    final Deferred<InstalledBehaviour> deferred;
    final Map<String, Path> files = new ConcurrentHashMap<>();
    /** Installer's thread only. */
    int rounds;
    /** Installer's thread only: its record was dropped because its bundle had been uninstalled behind our back. */
    boolean vanished;

    Job(BehaviourResource chosen, String reason, long installedAt, boolean operator,
            Deferred<InstalledBehaviour> deferred) {
        this.chosen = chosen;
        this.reason = reason;
        this.installedAt = installedAt;
        this.operator = operator;
        this.deferred = deferred;
    }
}
