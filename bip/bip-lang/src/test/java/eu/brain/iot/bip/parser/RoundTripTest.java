package eu.brain.iot.bip.parser;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;

import eu.brain.iot.bip.Models;
import eu.brain.iot.bip.SyntheticModel;
import eu.brain.iot.bip.diag.Diagnostics;
import eu.brain.iot.bip.model.BipPackage;
import eu.brain.iot.bip.print.Printer;

/** Printing a model and parsing the text gives back an equal model (positions aside), and printing is stable. */
class RoundTripTest {

    private static void assertRoundTrip(String name, String text) {
        Diagnostics d = new Diagnostics();
        BipPackage original = Parser.parse(name, text, d);
        assertThat(d.errors()).as(name).isEmpty();
        String printed = Printer.print(original);
        Diagnostics d2 = new Diagnostics();
        BipPackage reparsed = Parser.parse(name + " (printed)", printed, d2);
        assertThat(d2.errors()).as(printed).isEmpty();
        assertThat(reparsed).as(name).isEqualTo(original);
        assertThat(Printer.print(reparsed)).isEqualTo(printed);
    }

    @Test
    void goldenModels() {
        for (String name : List.of("package", "atom", "connector", "compound", "expressions", "bip2")) {
            assertRoundTrip(name, Models.resource("golden/" + name + ".bip"));
        }
    }

    @Test
    void warehouseBehaviours() throws IOException {
        List<Path> files = new ArrayList<>();
        for (Path dir : Models.BEHAVIOUR_DIRS) {
            try (Stream<Path> s = Files.list(dir)) {
                s.filter(p -> p.toString().endsWith(".bip")).forEach(files::add);
            }
        }
        assertThat(files).hasSize(5);
        for (Path f : files) {
            assertRoundTrip(f.toString(), Files.readString(f));
        }
    }

    @Test
    void syntheticModels() {
        for (long seed = 1; seed <= 20; seed++) {
            assertRoundTrip("synthetic-" + seed, SyntheticModel.of(300, seed));
        }
    }

    @Test
    void positionsAreNotPartOfEquality() {
        Diagnostics d = new Diagnostics();
        BipPackage a = Parser.parse("a.bip", "package P const data int x = 1 end", d);
        BipPackage b = Parser.parse("b.bip", "package P\n\n   const data int x =\n 1\nend", d);
        assertThat(a).isEqualTo(b);
        assertThat(a.decls().get(0).pos().sameAs(b.decls().get(0).pos())).isFalse();
    }
}
