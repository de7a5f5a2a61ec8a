package eu.brain.iot.scenario;

import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.Map;
import java.util.TreeMap;

import eu.brain.iot.federation.impl.FabricKey;

/**
 * Writes a node's configuration folder (what {@code -Dfelix.fileinstall.dir} points at): the files of
 * {@code node/config} (the Bundle Installer's repository and trusted key), with a journal of the node's own so that
 * the node starts bare; the edge pointed at this run's robot-sim with its poll period scaled to the speed (and, one
 * node of several, its leased share of the fleet); the behaviours' settings; the fabric's membership and the device
 * leases when the node joins a fabric; and the user's {@code --node-config} files. Stateless.
 */
final class NodeSetup {
    static final String BIS_PID = "eu.brain.iot.bis";
    static final String EDGE_PID = "eu.brain.iot.edge";
    static final String FEDERATION_PID = "eu.brain.iot.federation";
    static final String LEASE_PID = "eu.brain.iot.federation.lease";
    static final String BMS_PID = "eu.brain.iot.bms";
    /**
     * How long a node sharing the fleet holds the events that had a behaviour installed and that it does not take
     * (BMS {@code handover.grace.ms}): the robot behaviour of every node but one stands by, so the first robot events
     * of a node wait for the interest of the one that drives the fleet (decided within 6 s, FleetLeadership) and
     * reach it, rather than being given up.
     */
    static final long SHARED_FLEET_HANDOVER_GRACE_MS = 10_000;
    /** A device lease holds this long after it was sent (wall ms; federation/README.md, "Device leases"). */
    static final long LEASE_MS = Judge.DEFAULT_LEASE_MS;
    /** A node renews its lease this often (wall ms). */
    static final long RENEW_MS = 500;
    /** The node that owns every door when the fleet is shared. */
    static final int DOORS_OWNER = 1;

    /**
     * What a node needs to join the run's fabric.
     *
     * @param broker the broker's URI (the one given, or the embedded broker's)
     * @param key    the fabric's key file
     * @param fabric the fabric's name
     */
    record Join(String broker, Path key, String fabric) {
    }

    private NodeSetup() {
    }

    /**
     * @param node the node
     * @param join the fabric it joins, or null: it runs alone
     * @return the configuration folder
     */
    static Path write(Options o, URI fleet, NodeSpec node, Join join) throws IOException {
        Path dir = Files.createDirectories(node.configDir());
        Path nodeConfig = o.root().resolve("node/config");
        if (Files.isDirectory(nodeConfig)) {
            try (DirectoryStream<Path> files = Files.newDirectoryStream(nodeConfig, "*.{cfg,config}")) {
                for (Path f : files) {
                    Files.copy(f, dir.resolve(f.getFileName()), StandardCopyOption.REPLACE_EXISTING);
                }
            }
        }
        Path bis = dir.resolve(BIS_PID + ".cfg");
        if (!o.behaviours()) {
            // no installer configured: the node has no BIS and no BMS, so nothing installs a behaviour
            Files.deleteIfExists(bis);
        } else if (Files.isRegularFile(bis)) {
            // a journal of this run's own: behaviours installed by earlier runs are not restored at start
            Path journal = Files.createDirectories(node.folder().resolve("journal"));
            Files.writeString(bis, "\n# the scenario's own journal: the node starts bare\njournal.dir="
                    + journal + "\n", StandardCharsets.UTF_8, java.nio.file.StandardOpenOption.APPEND);
        } else {
            throw new IOException(nodeConfig.resolve(BIS_PID + ".cfg") + " is missing: the node would have no "
                    + "behaviour repository (use --no-behaviours to run without one on purpose)");
        }
        writeCfg(dir.resolve(EDGE_PID + ".cfg"), edge(o, fleet, node));
        for (Map.Entry<String, Map<String, Object>> pid : BehaviourSettings.forRun(o).entrySet()) {
            writeCfg(dir.resolve(pid.getKey() + ".cfg"), pid.getValue());
        }
        if (join != null) {
            writeCfg(dir.resolve(FEDERATION_PID + ".cfg"), federation(join, node));
        }
        if (node.shared()) {
            writeCfg(dir.resolve(LEASE_PID + ".cfg"), lease());
            writeCfg(dir.resolve(BMS_PID + ".cfg"), Map.<String, Object>of("handover.grace.ms",
                    SHARED_FLEET_HANDOVER_GRACE_MS));
        }
        for (Path extra : o.nodeConfigs()) {
            Files.copy(extra, dir.resolve(extra.getFileName()), StandardCopyOption.REPLACE_EXISTING);
        }
        return dir;
    }

    /** The edge's settings (PID eu.brain.iot.edge) of one node alone: the whole fleet. */
    static Map<String, Object> edge(Options o, URI fleet) {
        return edge(o, fleet, new NodeSpec(null, 1, 1, o.runDir(), 0));
    }

    /**
     * The edge's settings (PID eu.brain.iot.edge): this run's fleet, polled twice per step (0.5 s of warehouse
     * time, {@link Options#POLLS_PER_STEP}); one node of N owns the K-th share of the robots ({@code share=K/N}; the
     * doors on node {@value #DOORS_OWNER}), held by a lease so that the others take its devices when it dies
     * ({@code share.leased=true}).
     */
    static Map<String, Object> edge(Options o, URI fleet, NodeSpec node) {
        Map<String, Object> edge = new TreeMap<>();
        if (node.shared()) {
            edge.put("share", node.number() + "/" + node.of());
            edge.put("share.leased", true);
            edge.put("doors.owner", DOORS_OWNER);
        }
        edge.put("fleet.url", fleet.toString());
        edge.put("poll.period.ms", o.pollPeriodMs());
        // the edge's back-off for an unreachable robot, 8 s by default, is wall time: scale it too, so that a robot
        // back from a fault is seen within about 8 s of warehouse time
        edge.put("backoff.max.ms", Math.max(o.pollPeriodMs(), Math.round(8_000 / o.speed())));
        // where the carts stand (GET /world, 2 s by default), at the same pace in warehouse time
        edge.put("world.period.ms", Math.max(o.pollPeriodMs(), Math.round(2_000 / o.speed())));
        return edge;
    }

    /** The one node's membership in the fabric of {@code --broker} (see below). */
    static Map<String, Object> federation(Options o) throws IOException {
        return federation(new Join(o.fabric().broker(), key(o), o.fabric().name()), NodeSpec.forRun(o).get(0));
    }

    /**
     * The fabric's key: the one given, else a new one in the run's folder ({@code fabric.key}: 32 random bytes,
     * base64, owner-only permissions; federation/README.md, "Trust"), made once per run.
     */
    static Path key(Options o) throws IOException {
        Path key = o.fabric().key();
        if (key == null) {
            key = o.runDir().resolve("fabric.key");
            if (!Files.exists(key)) {
                Files.createDirectories(o.runDir());
                FabricKey.generate(key);
            }
        }
        return key;
    }

    /**
     * A node's membership in the fabric (PID eu.brain.iot.federation, federation/README.md): the broker, the
     * fabric's name, the key, a state folder of the node's own; one node of several is also named here (one node alone
     * has the name of the framework property the runner starts it with).
     */
    static Map<String, Object> federation(Join join, NodeSpec node) {
        Map<String, Object> fabric = new TreeMap<>();
        fabric.put("broker.uri", join.broker());
        fabric.put("fabric.name", join.fabric());
        if (node.shared()) {
            fabric.put("node.name", node.name());
        }
        fabric.put("key.file", join.key().toString());
        fabric.put("state.dir", node.folder().resolve("federation").toString());
        return fabric;
    }

    /** The device leases (PID eu.brain.iot.federation.lease) of a node that shares the fleet. */
    static Map<String, Object> lease() {
        Map<String, Object> lease = new TreeMap<>();
        lease.put("lease.ms", LEASE_MS);
        lease.put("renew.ms", RENEW_MS);
        return lease;
    }

    private static void writeCfg(Path file, Map<String, Object> properties) throws IOException {
        StringBuilder text = new StringBuilder("# written by the warehouse scenario runner for this run\n");
        properties.forEach((k, v) -> text.append(k).append('=').append(v).append('\n'));
        Files.writeString(file, text, StandardCharsets.UTF_8);
    }

    /** A port free on 127.0.0.1 now (the node binds it a moment later). */
    static int freePort() throws IOException {
        try (ServerSocket s = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            return s.getLocalPort();
        }
    }
}
