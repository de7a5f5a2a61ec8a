package eu.brain.iot.bip.parser;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import eu.brain.iot.bip.Models;
import eu.brain.iot.bip.diag.Diagnostics;
import eu.brain.iot.bip.model.BipPackage;

/**
 * Golden tests: for each construct of the language, the model the parser yields (every node and position) must
 * equal the reviewed dump in {@code src/test/resources/golden/<name>.model}. After an intended change, regenerate
 * with {@code -Dgolden.update=true} and review the diff.
 */
class GoldenTest {

    @ParameterizedTest
    @ValueSource(strings = {"package", "atom", "connector", "compound", "expressions", "bip2"})
    void parserYieldsTheGoldenModel(String name) throws IOException {
        Diagnostics diagnostics = new Diagnostics();
        BipPackage pkg = Parser.parse(name + ".bip", Models.resource("golden/" + name + ".bip"), diagnostics);
        assertThat(diagnostics.errors()).isEmpty();
        String actual = ModelDump.dump(pkg);
        Path golden = Path.of("src/test/resources/golden", name + ".model");
        if (Boolean.getBoolean("golden.update")) {
            Files.writeString(golden, actual, StandardCharsets.UTF_8);
        }
        assertThat(actual).isEqualTo(Files.readString(golden, StandardCharsets.UTF_8));
    }
}
