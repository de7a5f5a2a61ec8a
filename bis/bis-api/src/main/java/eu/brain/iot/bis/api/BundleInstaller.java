package eu.brain.iot.bis.api;

import java.util.List;
import java.util.Map;

import org.osgi.annotation.versioning.ProviderType;
import org.osgi.util.promise.Promise;

/**
 * Installs behaviours from repositories of behaviour bundles into a fabric node.
 * <p>
 * An install resolves the behaviour against the framework's bundles and the repositories (what it needs is installed
 * too), verifies every download against the index's SHA-256, starts the bundles in dependency order, and succeeds when
 * the behaviour's smart behaviours are registered with the event bus. It is transactional: when anything fails, every
 * bundle that request installed is uninstalled and the promise fails with an {@link InstallException}. Concurrent
 * requests for the same behaviour lead to one install; an installed but stopped behaviour is started again, not
 * installed twice. Shared dependencies are counted: uninstalling a behaviour removes only what no other installed
 * behaviour needs.
 * <p>
 * Threading: every method may be called from any thread and returns at once; the work happens on the installer's
 * own threads, and promises resolve there.
 */
@ProviderType
public interface BundleInstaller {

    /**
     * Behaviours in the repositories that consume any of the given event types, best first (configured
     * preferences, then highest version). A local installer answers from the indexes it holds in memory, with an
     * already resolved promise, so that a caller on a publisher's thread may use the answer at once when
     * {@code isDone()}.
     *
     * @param consumedTypes event type names, e.g. an event's type followed by its supertypes and interfaces
     */
    Promise<List<BehaviourCandidate>> find(List<String> consumedTypes);

    /**
     * As {@link #find(List)}, for one event that no behaviour takes: an installer that spans several nodes may use
     * its fields to choose the node (e.g. the node that owns the devices the event names); an installer of one
     * node answers as {@link #find(List)}, which this default does. Since 1.3.
     *
     * @param consumedTypes event type names, e.g. an event's type followed by its supertypes and interfaces
     * @param event the event's fields as an untyped behaviour gets them (a map; nested data as maps); not changed
     */
    default Promise<List<BehaviourCandidate>> find(List<String> consumedTypes, Map<String, ?> event) {
        return find(consumedTypes);
    }

    /** Install (or restart) a behaviour; resolves when its smart behaviours are registered with the bus. */
    Promise<InstalledBehaviour> install(InstallRequest request);

    /**
     * Uninstall a behaviour installed by this installer, and what it alone needed.
     *
     * @param symbolicName the behaviour bundle's symbolic name
     * @param reason why, recorded in the journal
     * @param byOperator {@code true} when a person asked for it: the behaviour is then not installed again by an
     *        automatic request ({@link InstallRequest#operator} {@code false}) until an operator installs or allows it
     */
    Promise<InstalledBehaviour> uninstall(String symbolicName, String reason, boolean byOperator);

    /** Lift an operator's removal: automatic requests may install the behaviour again. */
    void allow(String symbolicName);

    /** @return the behaviours this installer installed and that are still installed, oldest first */
    List<InstalledBehaviour> installed();

    /**
     * What the installer is doing now, for people: one line per piece of work under way, each naming the behaviour
     * and, for a download, its URL and progress (e.g. {@code downloading eu.brain.iot.door 1.0.0 from
     * http://host/door.jar: 1200 of 45000 bytes after 12 s}). Empty when it is idle, or when it does not tell.
     */
    default List<String> activities() {
        return List.of();
    }
}
