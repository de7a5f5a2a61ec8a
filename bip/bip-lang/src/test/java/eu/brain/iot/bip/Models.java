package eu.brain.iot.bip;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import eu.brain.iot.bip.check.ModelSet;
import eu.brain.iot.bip.check.Workspace;
import eu.brain.iot.bip.diag.Diagnostics;

/** Test helpers: models from text and from the repository's behaviours. */
public final class Models {

    /** The directories of the warehouse behaviours' models (behaviours/*\/src/main/bip). */
    public static final List<Path> BEHAVIOUR_DIRS = List.of("events", "robot", "door", "orchestrator").stream()
            .map(m -> Path.of("../../behaviours", m, "src/main/bip")).toList();

    private Models() {
    }

    /** Parses and checks in-memory sources (file name, text, file name, text, ...). */
    public static ModelSet check(String... namesAndTexts) {
        Workspace ws = new Workspace(List.of(), new Diagnostics());
        for (int i = 0; i < namesAndTexts.length; i += 2) {
            ws.addSource(namesAndTexts[i], namesAndTexts[i + 1]);
        }
        ws.resolveUses();
        ModelSet tool = ModelSet.of(ws);
        tool.check();
        return tool;
    }

    /** Loads the warehouse system (all four behaviour models) as the run's own packages. */
    public static ModelSet warehouse() {
        List<Path> files = BEHAVIOUR_DIRS.stream().flatMap(d -> list(d).stream()).toList();
        ModelSet tool = ModelSet.load(files, BEHAVIOUR_DIRS, new Diagnostics());
        tool.check();
        return tool;
    }

    static List<Path> list(Path dir) {
        try (var s = Files.list(dir)) {
            return s.filter(p -> p.toString().endsWith(".bip")).sorted().toList();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    public static String resource(String name) {
        try (var in = Models.class.getResourceAsStream("/" + name)) {
            if (in == null) {
                throw new IllegalArgumentException("no test resource " + name);
            }
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
