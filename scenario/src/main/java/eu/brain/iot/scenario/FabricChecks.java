package eu.brain.iot.scenario;

import java.io.IOException;
import java.nio.file.Files;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;

/**
 * The checks a run on a fabric of several nodes adds to the judge's: did every node join the fabric, did every
 * node the run did not kill run until the end, and did a node started again get a share of the fleet back.
 * Stateless.
 */
final class FabricChecks {
    private static final Duration SHELL_TIMEOUT = Duration.ofSeconds(20);

    private FabricChecks() {
    }

    /** Every node's log says it joined the run's fabric through its broker; else why not, per node. */
    static Verdict.Check joined(NodeGroup nodes) throws InterruptedException {
        NodeSetup.Join join = nodes.join();
        List<String> joined = new ArrayList<>();
        List<String> not = new ArrayList<>();
        for (NodeGroup.Member m : nodes.members()) {
            String line = "Fabric " + join.fabric() + ": node " + m.spec.name() + " joined through " + join.broker();
            try {
                if (Files.readString(m.node.log()).contains(line)) {
                    joined.add(m.spec.name());
                } else if (m.node.alive()) {
                    not.add(m.spec.name() + ": " + String.join(" ", m.node.shell("fabric:nodes", SHELL_TIMEOUT))
                            + " (its log: " + m.node.log() + ")");
                } else {
                    not.add(m.spec.name() + ": its log does not say so (" + m.node.log() + ")");
                }
            } catch (IOException e) {
                not.add(m.spec.name() + ": unknown (" + e.getMessage() + ")");
            }
        }
        return new Verdict.Check("every node joined the fabric " + join.fabric() + " through " + join.broker(),
                not.isEmpty(), not.isEmpty() ? String.join(", ", joined) + " joined"
                        : "not joined: " + String.join("; ", not));
    }

    /** Every node the run did not kill was still running at the end. */
    static Verdict.Check ranUntilTheEnd(NodeGroup nodes) {
        List<String> ended = new ArrayList<>();
        List<String> killed = new ArrayList<>();
        for (NodeGroup.Member m : nodes.members()) {
            if (m.killed()) {
                killed.add(m.spec.name());
            } else if (!m.node.alive()) {
                ended.add(m.spec.name() + " ended during the run (exit code " + m.node.exitCode() + "; its log: "
                        + m.node.log() + ")");
            }
        }
        return new Verdict.Check("every node not killed ran until the end", ended.isEmpty(), ended.isEmpty()
                ? nodes.members().size() - killed.size() + " of " + nodes.members().size() + " nodes running"
                        + (killed.isEmpty() ? "" : ", " + String.join(", ", killed) + " killed by the run")
                : String.join("; ", ended));
    }

    /**
     * Every node the run started again after killing it owns devices again at the end (it rejoined, listened, and
     * the nodes that held its share gave it back); null when no node was started again.
     */
    static Verdict.Check restartedTookAShare(NodeGroup nodes) {
        List<String> back = new ArrayList<>();
        List<String> not = new ArrayList<>();
        for (NodeGroup.Member m : nodes.members()) {
            if (!m.restarted()) {
                continue;
            }
            List<String> owned = m.owned();
            if (owned != null && !owned.isEmpty()) {
                back.add(m.spec.name() + " owns " + String.join(", ", owned));
            } else {
                not.add(m.spec.name() + (owned == null ? ": unknown (its REST API did not answer; its log: "
                        + m.node.log() + ")" : ": owns nothing (its log: " + m.node.log() + ")"));
            }
        }
        if (back.isEmpty() && not.isEmpty()) {
            return null;
        }
        return new Verdict.Check("every node started again got a share of the fleet back", not.isEmpty(),
                not.isEmpty() ? String.join("; ", back) : String.join("; ", not));
    }
}
