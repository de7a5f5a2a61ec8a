package eu.brain.iot.scenario;

import static org.assertj.core.api.Assertions.assertThat;

import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Properties;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import eu.brain.iot.federation.impl.FabricKey;

/** The configuration written for node K of N: its share, its lease, its fabric, its own folders and port. */
class NodeSetupFabricTest {
    private static final URI FLEET = URI.create("http://127.0.0.1:18090/");

    private static Options options(Path root, Path run, String... more) throws Exception {
        Files.createDirectories(root.resolve("node/config"));
        Files.writeString(root.resolve("node/config/eu.brain.iot.bis.cfg"), "repository.url=x\n");
        Files.writeString(root.resolve("node/config/eu.brain.iot.eventing.cfg"), "queue.capacity=100000\n");
        List<String> args = new java.util.ArrayList<>(List.of("--root", root.toString(), "--run-dir", run.toString()));
        args.addAll(List.of(more));
        return OptionsParser.parse(args.toArray(String[]::new));
    }

    private static Map<String, String> cfg(Path file) throws Exception {
        Properties p = new Properties();
        try (var in = Files.newBufferedReader(file, StandardCharsets.UTF_8)) {
            p.load(in);
        }
        return p.stringPropertyNames().stream().collect(Collectors.toMap(k -> k, p::getProperty));
    }

    @Test
    void eachNodeHasItsOwnFolderAndPort(@TempDir Path dir) throws Exception {
        Options o = options(dir.resolve("root"), dir.resolve("run"), "--nodes", "4");
        List<NodeSpec> nodes = NodeSpec.forRun(o);
        assertThat(nodes).extracting(NodeSpec::name).containsExactly("node1", "node2", "node3", "node4");
        assertThat(nodes).extracting(NodeSpec::number).containsExactly(1, 2, 3, 4);
        assertThat(nodes).allMatch(n -> n.of() == 4 && n.shared());
        assertThat(nodes).extracting(NodeSpec::folder).containsExactly(dir.resolve("run/node1"),
                dir.resolve("run/node2"), dir.resolve("run/node3"), dir.resolve("run/node4"));
        assertThat(nodes.stream().map(NodeSpec::httpPort).distinct().count()).as("distinct ports").isEqualTo(4);
        assertThat(nodes.get(1).log()).isEqualTo(dir.resolve("run/node2/node.log"));
        assertThat(nodes.get(1).configDir()).isEqualTo(dir.resolve("run/node2/node-config"));
    }

    @Test
    void oneNodeAloneKeepsTheRunsFolder(@TempDir Path dir) throws Exception {
        Options o = options(dir.resolve("root"), dir.resolve("run"));
        NodeSpec alone = NodeSpec.forRun(o).get(0);
        assertThat(alone.name()).isNull();
        assertThat(alone.shared()).isFalse();
        assertThat(alone.folder()).isEqualTo(dir.resolve("run"));
        assertThat(alone.log()).isEqualTo(dir.resolve("run/node.log"));

        Path config = NodeSetup.write(o, FLEET, alone, null);
        assertThat(config).isEqualTo(dir.resolve("run/node-config"));
        assertThat(cfg(config.resolve("eu.brain.iot.edge.cfg"))).doesNotContainKeys("share", "share.leased",
                "doors.owner");
        assertThat(config.resolve("eu.brain.iot.federation.cfg")).doesNotExist();
        assertThat(config.resolve("eu.brain.iot.federation.lease.cfg")).doesNotExist();
        assertThat(cfg(config.resolve("eu.brain.iot.bis.cfg"))).containsEntry("journal.dir",
                dir.resolve("run/journal").toString());
    }

    @Test
    void nodeKOfNOwnsItsLeasedShareInTheRunsFabric(@TempDir Path dir) throws Exception {
        Options o = options(dir.resolve("root"), dir.resolve("run"), "--nodes", "3");
        Path key = NodeSetup.key(o);
        assertThat(key).isEqualTo(dir.resolve("run/fabric.key"));
        assertThat(FabricKey.read(key)).as("a key the nodes read").isNotNull();
        NodeSetup.Join join = new NodeSetup.Join("tcp://127.0.0.1:18831", key, o.fabric().name());
        List<NodeSpec> nodes = NodeSpec.forRun(o);

        for (NodeSpec node : nodes) {
            Path config = NodeSetup.write(o, FLEET, node, join);
            Path folder = dir.resolve("run").resolve(node.name());
            assertThat(config).isEqualTo(folder.resolve("node-config"));

            Map<String, String> edge = cfg(config.resolve("eu.brain.iot.edge.cfg"));
            assertThat(edge).containsEntry("share", node.number() + "/3").containsEntry("share.leased", "true")
                    .containsEntry("doors.owner", "1").containsEntry("fleet.url", FLEET.toString())
                    .containsEntry("poll.period.ms", "50");

            assertThat(cfg(config.resolve("eu.brain.iot.federation.cfg")))
                    .containsEntry("broker.uri", "tcp://127.0.0.1:18831")
                    .containsEntry("fabric.name", o.fabric().name())
                    .containsEntry("node.name", node.name())
                    .containsEntry("key.file", key.toString())
                    .containsEntry("state.dir", folder.resolve("federation").toString());
            assertThat(cfg(config.resolve("eu.brain.iot.federation.lease.cfg")))
                    .containsExactlyInAnyOrderEntriesOf(Map.of("lease.ms", "2000", "renew.ms", "500"));
            assertThat(cfg(config.resolve("eu.brain.iot.bis.cfg"))).as("a journal of its own: it starts bare")
                    .containsEntry("journal.dir", folder.resolve("journal").toString());
            assertThat(config.resolve("eu.brain.iot.eventing.cfg")).as("node/config's files copied").isRegularFile();
        }
        assertThat(NodeSetup.key(o)).as("one key per run, made once").isEqualTo(key);
    }
}
