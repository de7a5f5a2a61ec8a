package eu.brain.iot.scenario;

import java.io.BufferedReader;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;

/**
 * What a node's log says kept it out of its fabric: the first line that says it does not join one (its key, its
 * configuration) or cannot reach the broker, without the logger's prefix. Read when the nodes' edges did not show
 * the fleet in time, so that the run names the cause, not only its effect.
 */
final class FabricTrouble {

    /** What the federation bundle logs when a node stays out of its fabric. */
    private static final List<String> SIGNS = List.of("does not join a fabric", "cannot reach the broker");
    /** Lines read at most: the first minute of a node's log. */
    private static final int MAX_LINES = 20_000;

    private FabricTrouble() {
    }

    /** @return the first line of the log that says why the node is not in its fabric, or empty */
    static Optional<String> in(Path log) {
        try (BufferedReader r = Files.newBufferedReader(log, StandardCharsets.UTF_8)) {
            int n = 0;
            for (String line = r.readLine(); line != null && n < MAX_LINES; line = r.readLine(), n++) {
                for (String sign : SIGNS) {
                    if (line.contains(sign)) {
                        int prefix = line.indexOf(" - ");
                        return Optional.of((prefix < 0 ? line : line.substring(prefix + 3)).trim());
                    }
                }
            }
        } catch (IOException e) {
            return Optional.empty(); // no log (yet): nothing to tell
        }
        return Optional.empty();
    }
}
