package eu.brain.iot.node;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The framework cache a node killed with SIGKILL leaves behind is removed by the next node that starts, and a live
 * node's cache is not. Each node runs with a temporary folder of the test's own ({@code java.io.tmpdir}), where bnd's
 * launcher makes the caches ({@code osgi.*.fw}).
 */
class FrameworkCacheTest {

    private static final String READY = "fabric node ready in ";
    private static final String MARKER = "fabric-node.pid";

    @TempDir
    Path tmp;
    @TempDir
    Path configDir;

    @Test
    void theNextStartRemovesTheCacheOfAKilledNodeAndKeepsALiveOnes() throws Exception {
        Path killedCache;
        Path liveCache;
        try (NodeProcess killed = start("-Dgosh.args=--nointeractive");
                NodeProcess live = start("-Dgosh.args=--nointeractive")) {
            killed.awaitOutput(READY);
            live.awaitOutput(READY);
            killedCache = cacheOf(killed);
            liveCache = cacheOf(live);

            killed.kill();
            assertThat(killedCache).as("no shutdown hook ran").isDirectory();

            try (NodeProcess next = start("-Dfabric.node.exitWhenReady=true")) {
                assertThat(next.awaitExit()).as("exit code; output:%n%s", next.output()).isZero();
                assertThat(next.output()).contains("removed the framework cache " + killedCache + " of node process "
                        + killed.pid() + ", which ended without stopping");
            }
            assertThat(killedCache).doesNotExist();
            assertThat(liveCache).as("a live node's cache").isDirectory();
            assertThat(caches()).containsExactly(liveCache);

            live.terminate();
            live.awaitExit();
        }
        assertThat(caches()).as("a node that stops removes its own cache").isEmpty();
    }

    private NodeProcess start(String mode) throws Exception {
        return NodeProcess.start(mode, "-Djava.io.tmpdir=" + tmp, "-Dfelix.fileinstall.dir=" + configDir,
                "-Dorg.osgi.service.http.port=" + NodeProcess.freePort());
    }

    /** The cache whose marker names the node's process. */
    private Path cacheOf(NodeProcess node) throws IOException {
        for (Path cache : caches()) {
            Path marker = cache.resolve(MARKER);
            if (Files.isRegularFile(marker) && Files.readString(marker).startsWith(node.pid() + " ")) {
                return cache;
            }
        }
        throw new AssertionError("no cache marked with pid " + node.pid() + " among " + caches());
    }

    private List<Path> caches() throws IOException {
        try (Stream<Path> files = Files.list(tmp)) {
            return files.filter(f -> f.getFileName().toString().matches("osgi\\..*\\.fw")).toList();
        }
    }

}
