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
 * Writes the run's node configuration folder (what {@code -Dfelix.fileinstall.dir} points at): the files of
 * {@code node/config} (the Bundle Installer's repository and trusted key), with a journal of the run's own so that
 * the node starts bare; the edge pointed at this run's robot-sim with its poll period scaled to the speed; the
 * behaviours' settings; and the user's {@code --node-config} files. Stateless.
 */
final class NodeSetup {
    static final String BIS_PID = "eu.brain.iot.bis";
    static final String EDGE_PID = "eu.brain.iot.edge";
    static final String FEDERATION_PID = "eu.brain.iot.federation";

    private NodeSetup() {
    }

    /** @return the configuration folder */
    static Path write(Options o, URI fleet) throws IOException {
        Path dir = Files.createDirectories(o.runDir().resolve("node-config"));
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
            Path journal = Files.createDirectories(o.runDir().resolve("journal"));
            Files.writeString(bis, "\n# the scenario's own journal: the node starts bare\njournal.dir="
                    + journal + "\n", StandardCharsets.UTF_8, java.nio.file.StandardOpenOption.APPEND);
        } else {
            throw new IOException(nodeConfig.resolve(BIS_PID + ".cfg") + " is missing: the node would have no "
                    + "behaviour repository (use --no-behaviours to run without one on purpose)");
        }
        writeCfg(dir.resolve(EDGE_PID + ".cfg"), edge(o, fleet));
        for (Map.Entry<String, Map<String, Object>> pid : BehaviourSettings.forRun(o).entrySet()) {
            writeCfg(dir.resolve(pid.getKey() + ".cfg"), pid.getValue());
        }
        if (o.fabric() != null) {
            writeCfg(dir.resolve(FEDERATION_PID + ".cfg"), federation(o));
        }
        for (Path extra : o.nodeConfigs()) {
            Files.copy(extra, dir.resolve(extra.getFileName()), StandardCopyOption.REPLACE_EXISTING);
        }
        return dir;
    }

    /** The edge's settings (PID eu.brain.iot.edge): this run's fleet, polled every 0.5 s of warehouse time. */
    static Map<String, Object> edge(Options o, URI fleet) {
        Map<String, Object> edge = new TreeMap<>();
        edge.put("fleet.url", fleet.toString());
        edge.put("poll.period.ms", o.pollPeriodMs());
        // the edge's back-off for an unreachable robot, 8 s by default, is wall time: scale it too, so that a robot
        // back from a fault is seen within about 8 s of warehouse time
        edge.put("backoff.max.ms", Math.max(o.pollPeriodMs(), Math.round(8_000 / o.speed())));
        // where the carts stand (GET /world, 2 s by default), at the same pace in warehouse time
        edge.put("world.period.ms", Math.max(o.pollPeriodMs(), Math.round(2_000 / o.speed())));
        return edge;
    }

    /**
     * The node's membership in the fabric (PID eu.brain.iot.federation, federation/README.md): the broker, the
     * fabric's name (the node's is the framework property the runner starts it with), the key (the one given, else a new one in the run's folder), a state folder of
     * the run's own.
     */
    static Map<String, Object> federation(Options o) throws IOException {
        Path key = o.fabric().key();
        if (key == null) {
            key = o.runDir().resolve("fabric.key");
            if (!Files.exists(key)) {
                FabricKey.generate(key);
            }
        }
        Map<String, Object> fabric = new TreeMap<>();
        fabric.put("broker.uri", o.fabric().broker());
        fabric.put("fabric.name", Options.Fabric.NAME);
        fabric.put("key.file", key.toString());
        fabric.put("state.dir", o.runDir().resolve("federation").toString());
        return fabric;
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
