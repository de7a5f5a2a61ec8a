package eu.brain.iot.bip.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code bip smc}: the table, CSV and SVG outputs, errors at their position in the option, exit codes. */
class SmcCommandTest {

    private static final String DICE = "src/test/resources/smc/KnuthYao.bip";

    @TempDir
    Path dir;

    private final ByteArrayOutputStream out = new ByteArrayOutputStream();
    private final ByteArrayOutputStream err = new ByteArrayOutputStream();

    private int run(String... args) {
        return Main.run(args, new PrintStream(out, true, StandardCharsets.UTF_8),
                new PrintStream(err, true, StandardCharsets.UTF_8));
    }

    @Test
    void answersASweepAsTableCsvAndPlot() throws Exception {
        Path csv = dir.resolve("r.csv");
        Path svg = dir.resolve("r.svg");
        assertThat(run("smc", DICE, "--property", "P=? [ F<=100 die.d == f ] for f = 1:6:1", "--epsilon", "0.05",
                "--threads", "2", "--csv", csv.toString(), "--svg", svg.toString())).as(err.toString()).isZero();
        String table = out.toString(StandardCharsets.UTF_8);
        assertThat(table).contains("f=1").contains("f=6").contains("Okamoto/Clopper-Pearson").contains("1060");
        assertThat(Files.readAllLines(csv)).hasSize(7).first().asString().startsWith("query,formula,parameters");
        assertThat(Files.readString(svg)).startsWith("<svg").contains("<polyline").contains("die.d == f");
    }

    @Test
    void aBadQueryIsReportedAtItsPositionInTheOption() {
        assertThat(run("smc", DICE, "--property", "P=? [ F<=10 die.face == 1 ]")).isEqualTo(1);
        assertThat(err.toString(StandardCharsets.UTF_8))
                .contains("--property:1:17: error: component die (Die) has no data face (data: s, d)")
                .doesNotContain("\tat ");
    }

    @Test
    void aRefutedRequirementExitsWithOneAndBadOptionsWithTwo() {
        assertThat(run("smc", DICE, "--property", "P>=0.5 [ F<=100 die.d == 1 ]", "--threads", "2")).isEqualTo(1);
        assertThat(err.toString(StandardCharsets.UTF_8)).contains("1 requirement(s) refuted");
        assertThat(out.toString(StandardCharsets.UTF_8)).contains("REFUTED").contains("SPRT");
        assertThat(run("smc", DICE, "--property", "P=? [ true ]", "--epsilon", "2")).isEqualTo(2);
        assertThat(run("smc", DICE)).isEqualTo(2);
    }
}
