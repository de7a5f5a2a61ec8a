package eu.brain.iot.node.state;

import java.nio.file.Path;

/**
 * A service of the node's own: its state folder is locked for it. Registered by {@link NodeState} only while the lock
 * is held. Immutable.
 *
 * @param folder the node's state folder
 */
public record StateHeld(Path folder) {
}
