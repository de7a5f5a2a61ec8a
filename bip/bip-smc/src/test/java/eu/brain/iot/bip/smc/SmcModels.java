package eu.brain.iot.bip.smc;

import java.nio.file.Path;
import java.util.List;

import eu.brain.iot.bip.diag.Diagnostics;

/** Loads the test models of {@code src/test/resources/smc}. */
final class SmcModels {

    static final Path DIR = Path.of("src/test/resources/smc");
    static final Path WAREHOUSE = DIR.resolve("prism-warehouse/Warehouse3.bip");

    private SmcModels() {
    }

    static SmcSession load(Path file) {
        Diagnostics d = new Diagnostics();
        return SmcSession.load(List.of(file), List.of(file.getParent()), null, d)
                .orElseThrow(() -> new AssertionError("model does not check: " + d));
    }

    static SmcSession load(String name) {
        return load(DIR.resolve(name + ".bip"));
    }
}
