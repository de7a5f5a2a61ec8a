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
 * which behaviours an operator removed; every change is written to the {@link Journal} at once, all or nothing: when
 * the journal cannot be written (a full disk, a read-only folder), the change is undone in memory too and the caller
 * gets the {@link IOException}, so that what the installer says matches what a restart would find. Journal entries
 * not (yet) installed again after a start are kept as {@code pending}, so that they stay in the journal.
 * <p>
 * Threads: changed mostly on the installer's thread ({@code allow} also on a caller's), read by any (Gogo,
 * {@code installed()}): every method is {@code synchronized}, journal writes included.
 */
final class Ledger {

    private final Journal journal;
    /** Told when only the history (for people) could not be written: the journal itself is the truth. */
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

    synchronized void put(BehaviourRecord record, String history) throws IOException {
        change(() -> {
            behaviours.remove(record.symbolicName());
            behaviours.put(record.symbolicName(), record);
            pending.remove(record.symbolicName());
        }, history, record.symbolicName(), record.version(), record.reason());
    }

    /** Takes a journal entry back into use without a history line (it was installed before this start). */
    synchronized void adopt(BehaviourRecord record) {
        behaviours.put(record.symbolicName(), record);
        pending.remove(record.symbolicName());
    }

    /** Records that an installed behaviour, found not active, was started again (a history line only). */
    synchronized void restarted(BehaviourRecord record, String why, long at) {
        Restart last = restarts.get(record.symbolicName());
        restarts.put(record.symbolicName(), new Restart(at, why, last == null ? 1 : last.count() + 1));
        history("restarted", record.symbolicName(), record.version(), why);
    }

    synchronized Optional<Restart> lastRestart(String symbolicName) {
        return Optional.ofNullable(restarts.get(symbolicName));
    }

    synchronized void remove(String symbolicName, String what, String reason) throws IOException {
        BehaviourRecord record = behaviours.containsKey(symbolicName) ? behaviours.get(symbolicName)
                : pending.get(symbolicName);
        change(() -> {
            restarts.remove(symbolicName);
            behaviours.remove(symbolicName);
            pending.remove(symbolicName);
        }, what, symbolicName, record == null ? null : record.version(), reason);
    }

    /** @return the journal entry not (yet) installed again under that name, if any */
    synchronized Optional<BehaviourRecord> pendingEntry(String symbolicName) {
        return Optional.ofNullable(pending.get(symbolicName));
    }

    synchronized boolean isBlocked(String symbolicName) {
        return blocked.containsKey(symbolicName);
    }

    /** @param what the history line's word: {@code removed-by-operator} or {@code stopped-by-operator} */
    synchronized void block(String symbolicName, String what, String reason) throws IOException {
        change(() -> blocked.put(symbolicName, reason), what, symbolicName, null, reason);
    }

    synchronized boolean allow(String symbolicName, String why) throws IOException {
        if (!blocked.containsKey(symbolicName)) {
            return false;
        }
        change(() -> blocked.remove(symbolicName), "allowed", symbolicName, null, why);
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

    /**
     * Makes a change in memory, writes the journal, and adds a history line; when the journal cannot be written, the
     * change is undone in memory and the error thrown. Called under {@code this}.
     */
    private void change(Runnable mutation, String what, String symbolicName, String version, String reason)
            throws IOException {
        Map<String, BehaviourRecord> behavioursBefore = new LinkedHashMap<>(behaviours);
        Map<String, BehaviourRecord> pendingBefore = new LinkedHashMap<>(pending);
        Map<String, String> blockedBefore = new LinkedHashMap<>(blocked);
        Map<String, Restart> restartsBefore = new LinkedHashMap<>(restarts);
        mutation.run();
        List<BehaviourRecord> all = new ArrayList<>(behaviours.values());
        all.addAll(pending.values());
        try {
            journal.save(new Journal.State(all, blocked));
        } catch (IOException e) {
            restore(behaviours, behavioursBefore);
            restore(pending, pendingBefore);
            restore(blocked, blockedBefore);
            restore(restarts, restartsBefore);
            throw new IOException("cannot write the journal " + journal.file() + " (" + Journal.describe(e) + "): '"
                    + what + " " + symbolicName + "' was not done; free space on that disk or make the folder"
                    + " writable (or set journal.dir of eu.brain.iot.bis), then try again", e);
        }
        history(what, symbolicName, version, reason);
    }

    private static <V> void restore(Map<String, V> map, Map<String, V> before) {
        map.clear();
        map.putAll(before);
    }

    private void history(String what, String symbolicName, String version, String reason) {
        try {
            journal.history(what, symbolicName, version, reason);
        } catch (IOException e) {
            error.accept("cannot add to the history " + journal.directory().resolve("history.log") + " ("
                    + Journal.describe(e) + "): '" + what + " " + symbolicName + "' is done and in the journal, only"
                    + " its line for people is missing; check the folder's free space and permissions");
        }
    }
}
