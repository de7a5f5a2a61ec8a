package eu.brain.iot.bip.cli;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code bip smc}: the table, CSV and SVG outputs, errors at their position in the option, messages, exit codes. */
class SmcCommandTest {

    /** The model checker's test models. */
    private static final String MODELS = "../bip-smc/src/test/resources/smc/";
    private static final String DICE = MODELS + "KnuthYao.bip";
    private static final Duration PROMPT = Duration.ofSeconds(60);

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

    @Test
    void theRefutedCountStartsALineOfItsOwnAfterTheReport() {
        ByteArrayOutputStream both = new ByteArrayOutputStream();
        PrintStream terminal = new PrintStream(both, true, StandardCharsets.UTF_8);
        assertThat(Main.run(new String[] {"smc", DICE, "--property", "P>=0.5 [ F<=100 die.d == 1 ]", "--threads", "2"},
                terminal, terminal)).isEqualTo(1);
        String text = both.toString(StandardCharsets.UTF_8);
        assertThat(text).contains("REFUTED").endsWith("(SPRT)\nbip: 1 requirement(s) refuted\n");
    }

    @Test
    void aFailingExternSimulationIsOneLineAndExitsWithOne() {
        int code = assertTimeoutPreemptively(PROMPT, () -> run("smc", MODELS + "Sensor.bip", "--property",
                "P=? [ F<=10 s.v == 2 ]", "--externs", FlakySensor.class.getName(), "--threads", "2", "--quiet"));
        String stderr = err.toString(StandardCharsets.UTF_8);
        assertThat(code).as(stderr).isEqualTo(1);
        assertThat(stderr.strip()).startsWith("bip: trace ").contains("sensor 7 unplugged").doesNotContain("\tat ");
        assertThat(stderr.strip().lines()).hasSize(1);
    }

    @Test
    void helpIsTheUsageOnStdoutWithZero() {
        assertThat(run("smc", "--help")).isZero();
        assertThat(run("smc", "-h")).isZero();
        assertThat(out.toString(StandardCharsets.UTF_8)).startsWith(SmcCommand.USAGE + SmcCommand.USAGE);
        assertThat(err.toString(StandardCharsets.UTF_8)).isEmpty();
    }

    @Test
    void badCommandLinesSayWhatIsWrongThenTheUsageAndExitWithTwo() {
        assertThat(run("smc", DICE)).isEqualTo(2);
        assertThat(err.toString(StandardCharsets.UTF_8)).isEqualTo("bip: smc needs a model file and at least one "
                + "--property or --properties\n" + SmcCommand.USAGE + "\n");
        err.reset();
        assertThat(run("smc", DICE, "--property")).isEqualTo(2);
        assertThat(err.toString(StandardCharsets.UTF_8)).isEqualTo("bip: --property needs a value\n"
                + SmcCommand.USAGE + "\n");
        err.reset();
        assertThat(run("smc", DICE, "--property", "P=? [ true ]", "--bogus")).isEqualTo(2);
        assertThat(err.toString(StandardCharsets.UTF_8)).isEqualTo("bip: unknown option --bogus\n"
                + SmcCommand.USAGE + "\n");
        err.reset();
        assertThat(run("smc", DICE, "--property", "P=? [ true ]", "--threads", "x")).isEqualTo(2);
        assertThat(err.toString(StandardCharsets.UTF_8))
                .isEqualTo("bip: --threads: option threads needs a number, found 'x'\n");
        err.reset();
        assertThat(run("smc", DICE, "--property", "P=? [ true ]", "--engine", "foo")).isEqualTo(2);
        assertThat(err.toString(StandardCharsets.UTF_8)).startsWith("bip: --engine: option engine: unknown value 'foo'");
        assertThat(out.toString(StandardCharsets.UTF_8)).isEmpty();
    }

    @Test
    void aMissingModelFileIsAnErrorWithOne() {
        assertThat(run("smc", DICE, "--property", "P=? [ true ]", "nope.bip")).isEqualTo(1);
        assertThat(err.toString(StandardCharsets.UTF_8))
                .isEqualTo("nope.bip:1:1: error: cannot read the file: nope.bip\nbip: 1 error(s)\n");
    }

    @Test
    void aNegativeSeedIsAValueNotAnOption() {
        assertThat(run("smc", DICE, "--property", "P=? [ true ]", "--seed", "-1", "--epsilon", "0.05")).isZero();
        assertThat(out.toString(StandardCharsets.UTF_8)).contains("seed -1, epsilon 0.05");
    }
}
