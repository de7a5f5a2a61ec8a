package eu.brain.iot.bis.impl.install;

import java.io.IOException;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.function.Consumer;

import eu.brain.iot.bis.impl.journal.BehaviourRecord;
import eu.brain.iot.bis.impl.journal.BundleFact;
import eu.brain.iot.bis.impl.journal.Journal;

/**
 * What the installer installed (behaviours and the bundles each needs, so that shared bundles are counted) and
 * which behaviours an operator removed; every change is written to the {@link Journal} at once. Journal entries not
 * (yet) installed again after a start are kept as {@code pending}, so that they stay in the journal.
 * <p>
 * Threads: changed mostly on the installer's thread ({@code allow} also on a caller's), read by any (Gogo,
 * {@code installed()}): every method is {@code synchronized}, journal writes included.
 */
final class Ledger {

    private final Journal journal;
    private final Consumer<String> error;
    private final Map<String, BehaviourRecord> behaviours = new LinkedHashMap<>();
    private final Map<String, BehaviourRecord> pending = new LinkedHashMap<>();
    private final Map<String, String> blocked = new LinkedHashMap<>();
    /** The last time each installed behaviour was started again, and why (since this start of the installer). */
    private final Map<String, Restart> restarts = new LinkedHashMap<>();

    Ledger(Journal journal, Journal.State loaded, Consumer<String> error) {
        this.journal = journal;
        this.error = error;
        loaded.behaviours().forEach(r -> pending.put(r.symbolicName(), r));
        blocked.putAll(loaded.blocked());
    }

    synchronized Optional<BehaviourRecord> get(String symbolicName) {
        return Optional.ofNullable(behaviours.get(symbolicName));
    }

    synchronized List<BehaviourRecord> behaviours() {
        return new ArrayList<>(behaviours.values());
    }

    synchronized List<BehaviourRecord> pending() {
        return new ArrayList<>(pending.values());
    }

    synchronized void put(BehaviourRecord record, String history) {
        behaviours.remove(record.symbolicName());
        behaviours.put(record.symbolicName(), record);
        pending.remove(record.symbolicName());
        save("installed".equals(history) ? "installed" : history, record.symbolicName(), record.version(),
                record.reason());
    }

    /** Takes a journal entry back into use without a history line (it was installed before this start). */
    synchronized void adopt(BehaviourRecord record) {
        behaviours.put(record.symbolicName(), record);
        pending.remove(record.symbolicName());
    }

    /** Records that an installed behaviour, found not active, was started again (a history line). */
    synchronized void restarted(BehaviourRecord record, String why, long at) {
        Restart last = restarts.get(record.symbolicName());
        restarts.put(record.symbolicName(), new Restart(at, why, last == null ? 1 : last.count() + 1));
        save("restarted", record.symbolicName(), record.version(), why);
    }

    synchronized Optional<Restart> lastRestart(String symbolicName) {
        return Optional.ofNullable(restarts.get(symbolicName));
    }

    synchronized void remove(String symbolicName, String what, String reason) {
        restarts.remove(symbolicName);
        BehaviourRecord record = behaviours.remove(symbolicName);
        pending.remove(symbolicName);
        save(what, symbolicName, record == null ? null : record.version(), reason);
    }

    /** Forgets a journal entry that cannot be installed again (its index no longer offers it). */
    synchronized void dropPending(String symbolicName, String reason) {
        if (pending.remove(symbolicName) != null) {
            save("forgotten", symbolicName, null, reason);
        }
    }

    synchronized boolean isBlocked(String symbolicName) {
        return blocked.containsKey(symbolicName);
    }

    /** @param what the history line's word: {@code removed-by-operator} or {@code stopped-by-operator} */
    synchronized void block(String symbolicName, String what, String reason) {
        blocked.put(symbolicName, reason);
        save(what, symbolicName, null, reason);
    }

    synchronized boolean allow(String symbolicName, String why) {
        if (blocked.remove(symbolicName) == null) {
            return false;
        }
        save("allowed", symbolicName, null, why);
        return true;
    }

    synchronized Map<String, String> blocked() {
        return new LinkedHashMap<>(blocked);
    }

    /** @return how many installed behaviours other than {@code except} list a bundle at this location */
    synchronized int otherUsers(String location, String except) {
        int users = 0;
        for (BehaviourRecord r : behaviours.values()) {
            if (!r.symbolicName().equals(except) && r.bundles().stream().anyMatch(b -> b.location().equals(location))) {
                users++;
            }
        }
        return users;
    }

    /** @return the installer's facts of a bundle at this location, if an installed behaviour lists it */
    synchronized Optional<BundleFact> bundle(String location) {
        return behaviours.values().stream().flatMap(r -> r.bundles().stream())
                .filter(b -> b.location().equals(location)).findFirst();
    }

    private void save(String what, String symbolicName, String version, String reason) {
        List<BehaviourRecord> all = new ArrayList<>(behaviours.values());
        all.addAll(pending.values());
        try {
            journal.save(new Journal.State(all, blocked));
            journal.history(what, symbolicName, version, reason);
        } catch (IOException e) {
            error.accept("cannot write the journal in " + journal.directory() + " (" + e + "): '" + what + " "
                    + symbolicName + "' is done but will not survive a restart; check the directory's permissions"
                    + " and free space, or set journal.dir of eu.brain.iot.bis");
        }
    }
}
