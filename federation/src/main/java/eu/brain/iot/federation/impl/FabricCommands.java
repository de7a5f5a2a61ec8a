package eu.brain.iot.federation.impl;

import java.io.IOException;
import java.nio.file.Path;

import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.component.annotations.ReferenceCardinality;
import org.osgi.service.component.annotations.ReferencePolicy;

/**
 * Gogo commands {@code fabric:nodes}, {@code fabric:interest [node]}, {@code fabric:stats} and
 * {@code fabric:keygen FILE}. Active with or without a fabric configuration (a key is made before a node joins).
 * Errors come back as messages: these are typed by a person.
 */
@Component(service = FabricCommands.class, property = { "osgi.command.scope=fabric", "osgi.command.function=nodes",
        "osgi.command.function=interest", "osgi.command.function=stats", "osgi.command.function=keygen" })
public final class FabricCommands {

    static final String NOT_CONFIGURED = "This node is not a member of a fabric: configure PID " + FabricConfig.PID
            + " (broker.uri, fabric.name, key.file; see federation/README.md).";

    @Reference(cardinality = ReferenceCardinality.OPTIONAL, policy = ReferencePolicy.DYNAMIC)
    private volatile FabricComponent fabric;

    /** The fabric's nodes: presence and how many interest entries each announces. */
    public String nodes() {
        FabricNode node = node();
        if (node == null) {
            return why();
        }
        StringBuilder out = new StringBuilder(String.format("fabric %s, broker %s%n%-24s %-20s %s%n",
                node.settings().fabric(), node.settings().brokerUri(), "NODE", "STATUS", "INTEREST ENTRIES"));
        node.nodes().forEach(v -> out.append(String.format("%-24s %-20s %d%n", v.node(), v.status(),
                v.interest().size())));
        return out.toString();
    }

    /** What the behaviours of every node (or one) consume. */
    public String interest(String... only) {
        FabricNode node = node();
        if (node == null) {
            return why();
        }
        StringBuilder out = new StringBuilder();
        node.nodes().stream().filter(v -> only.length == 0 || v.node().equals(only[0])).forEach(v -> {
            out.append(v.node()).append(" (").append(v.status()).append(")\n");
            if (v.interest().isEmpty()) {
                out.append("  (no behaviour)\n");
            }
            v.interest().forEach(e -> out.append("  ").append(String.join(",", e.types()))
                    .append(e.filter() == null ? "" : " where " + e.filter()).append('\n'));
        });
        return out.length() == 0 ? "fabric:interest: no node named " + only[0] + " (fabric:nodes lists them)"
                : out.toString();
    }

    /** Per remote node: events sent, resent, acknowledged, received, duplicates dropped, refused, backlog. */
    public String stats() {
        FabricNode node = node();
        if (node == null) {
            return why();
        }
        StringBuilder out = new StringBuilder(String.format("%-20s %10s %8s %10s %10s %10s %8s %8s %8s %8s %8s%n",
                "NODE", "SENT", "RESENT", "ACKED", "RECEIVED", "DUPLICATE", "REFUSED", "UNSIGNED", "BAD-SIG",
                "REPLAYED", "BACKLOG"));
        node.nodes().stream().filter(v -> !v.node().equals(node.name())).forEach(v -> {
            NodeStats.Snapshot s = v.stats();
            out.append(String.format("%-20s %10d %8d %10d %10d %10d %8d %8d %8d %8d %8d%n", v.node(), s.sent(),
                    s.resent(), s.acked(), s.received(), s.duplicates(), s.refused(), s.unsigned(), s.badSignature(),
                    s.replayed(), s.backlog()));
        });
        // refusals from names no verified message came from, and on this node's own topics: one row, so that a
        // client without the key adds no row
        NodeStats.Snapshot u = node.unverified();
        out.append(String.format("%-20s %10s %8s %10s %10s %10s %8d %8d %8d %8d %8s%n", Refusals.UNVERIFIED, "-", "-",
                "-", "-", "-", u.refused(), u.unsigned(), u.badSignature(), u.replayed(), "-"));
        return out.toString();
    }

    /** Create a fabric key file (every node of the fabric needs a copy). */
    public String keygen(String file) {
        try {
            FabricKey.generate(Path.of(file));
            return "fabric key written to " + Path.of(file).toAbsolutePath() + "; copy it to every node of the "
                    + "fabric (owner-only permissions) and set key.file in PID " + FabricConfig.PID + "; a node reads "
                    + "it when it starts or its configuration changes (start a running node again to join with it)";
        } catch (IOException | RuntimeException e) {
            return "fabric:keygen: " + e.getMessage();
        }
    }

    private FabricNode node() {
        FabricComponent f = fabric;
        return f == null ? null : f.node();
    }

    private String why() {
        FabricComponent f = fabric;
        return f == null ? NOT_CONFIGURED : "This node did not join its fabric: " + f.problem();
    }
}
