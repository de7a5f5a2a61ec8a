package eu.brain.iot.behaviours.robot.impl;

import java.util.HashSet;
import java.util.Set;
import java.util.concurrent.TimeUnit;

/**
 * Which nodes the binding may send model inputs to now. A node whose host has not reported may have no robot behaviour
 * yet: its first input has the BMS install it there, and the BMS takes the inputs of one type it holds meanwhile as
 * one install, so inputs for a second such node held with them would be left untaken. Such nodes are therefore sent
 * inputs one at a time: the next once the one before has reported, or after {@link #INSTALL_NANOS}.
 * Threads: the binding's thread only.
 */
final class HostInstalls {

    /** Wall time a node without a host may take to have one installed before another such node is sent inputs. */
    static final long INSTALL_NANOS = TimeUnit.SECONDS.toNanos(30);

    private final String self;
    /** The nodes whose host has reported: each has the robot behaviour. */
    private final Set<String> hosts = new HashSet<>();
    /** The node without a host sent inputs now, and since when; null for none. */
    private String installing;
    private long installingSince;

    /** @param self this binding's node, whose host is in the same bundle */
    HostInstalls(String self) {
        this.self = self;
    }

    /** A report came from the node's host. */
    void reported(String node) {
        hosts.add(node);
    }

    /** @return whether an input may go to the node now */
    boolean mayFire(String node, long nowNanos) {
        if (node.equals(self) || hosts.contains(node)) {
            return true;
        }
        if (installing == null || hosts.contains(installing) || nowNanos - installingSince >= INSTALL_NANOS) {
            installing = node;
            installingSince = nowNanos;
        }
        return installing.equals(node);
    }
}
