package eu.brain.iot.bip.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The command-line tool: exit codes, messages on stderr, generated files, never a stack trace. */
class MainTest {

    @TempDir
    Path dir;

    private final ByteArrayOutputStream out = new ByteArrayOutputStream();
    private final ByteArrayOutputStream err = new ByteArrayOutputStream();

    private int run(String... args) {
        return Main.run(args, new PrintStream(out, true, StandardCharsets.UTF_8),
                new PrintStream(err, true, StandardCharsets.UTF_8));
    }

    private String err() {
        return err.toString(StandardCharsets.UTF_8);
    }

    @Test
    void checkReportsEveryErrorWithPositionAndFailsWithoutAStackTrace() throws Exception {
        Path model = dir.resolve("Bad.bip");
        Files.writeString(model, "package Bad\n  port type T(\n  atom type A()\n    place S\n    initial to Q\n  end\nend\n");
        assertThat(run("check", model.toString())).isEqualTo(1);
        assertThat(err()).contains(model + ":3:3: error: expected a parameter type of port type T, found 'atom'")
                .contains(model + ":5:5: error: unknown place 'Q' after 'initial to' in atom type A; places are [S]")
                .contains("bip: 2 error(s)").doesNotContain("Exception").doesNotContain("\tat ");
    }

    @Test
    void checkAndGenerateTheWarehouse() throws Exception {
        String[] files = {"../../behaviours/events/src/main/bip/WarehouseSystem.bip",
            "../../behaviours/robot/src/main/bip/Robot.bip", "../../behaviours/door/src/main/bip/Door.bip",
            "../../behaviours/orchestrator/src/main/bip/Orchestrator.bip"};
        assertThat(run("check", files[0], files[1], files[2], files[3], "-I", "../../behaviours/events/src/main/bip"))
                .as(err()).isZero();
        Path output = dir.resolve("gen");
        assertThat(run("generate", files[0], files[1], files[2], files[3], "-I", "../../behaviours/events/src/main/bip",
                "-o", output.toString())).as(err()).isZero();
        assertThat(output.resolve("eu/brain/iot/behaviours/robot/RobotSmartBehaviour.java")).exists();
        assertThat(output.resolve("eu/brain/iot/behaviours/events/ConnectorResolveCollision.java")).exists();
        // 20 files: the collision-resolved connector is a broadcast (no offer event of its own)
        assertThat(out.toString(StandardCharsets.UTF_8)).contains("bip: wrote 20 Java file(s)");
    }

    @Test
    void aSystemThatCannotRunOnTheBusStillGetsItsAtomClassesUnlessStrict() throws Exception {
        Path model = dir.resolve("Hier.bip");
        Files.writeString(model, """
                package Hier
                  port type P()
                  atom type A()
                    export port P p()
                    place S
                    initial to S
                    on p from S to S
                  end
                  connector type Two(P a, P b)
                    export port P ep()
                    define a b
                  end
                  connector type Up(P x, P y)
                    define x y
                  end
                  compound type C()
                    component A a1(), a2(), a3()
                    connector Two t(a1.p, a2.p)
                    connector Up u(t.ep, a3.p)
                  end
                end
                """);
        Path output = dir.resolve("gen");
        assertThat(run("generate", model.toString(), "-o", output.toString())).as(err()).isZero();
        assertThat(err()).contains("warning: connector u is hierarchical").contains("the atom classes are");
        assertThat(output.resolve("hier/A.java")).exists();
        assertThat(output.resolve("hier/ABehaviour.java")).doesNotExist();
        assertThat(run("generate", model.toString(), "-o", dir.resolve("gen2").toString(), "--strict")).isEqualTo(1);
        assertThat(err()).contains("error: connector u is hierarchical");
    }

    @Test
    void badCommandLinesExitWithTwoAndUsage() {
        assertThat(run()).isEqualTo(2);
        assertThat(run("frobnicate", "x.bip")).isEqualTo(2);
        assertThat(run("generate", "x.bip")).isEqualTo(2);
        assertThat(err()).contains("usage: bip check FILE...");
    }

    @Test
    void aMissingFileIsAnErrorNotACrash() {
        assertThat(run("check", dir.resolve("nope.bip").toString())).isEqualTo(1);
        assertThat(err()).contains("nope.bip:1:1: error: cannot read the file");
    }

    @Test
    void aMissingUsedPackageNamesTheModelPath() throws Exception {
        Path model = dir.resolve("U.bip");
        Files.writeString(model, "package U\n  use Missing\nend\n");
        assertThat(run("check", model.toString())).isEqualTo(1);
        assertThat(err()).contains(model + ":2:3: error: package Missing not found: add -I <folder holding Missing.bip> "
                + "(Maven: a <modelPath> entry), or name its file; the model path is [" + dir + "]");
    }

    private static final String B = "../../behaviours/";

    @Test
    void oneMissingModelFolderIsOneErrorWithTheFlagToAdd() throws Exception {
        Path robot = Path.of(B + "robot/src/main/bip/Robot.bip");
        assertThat(run("generate", robot.toString(), "-o", dir.resolve("gen").toString())).isEqualTo(1);
        // The model changes as the warehouse grows: where its 'use Warehouse' stands is read from the file.
        List<String> lines = Files.readAllLines(robot);
        int use = lines.indexOf(lines.stream().filter(l -> l.trim().equals("use Warehouse")).findFirst().orElseThrow());
        int column = lines.get(use).indexOf("use") + 1;
        // without the folder of Warehouse.bip every port type and constant of Robot.bip is unknown: one error is shown,
        // the unknown names that follow from it are counted
        assertThat(err()).startsWith(B + "robot/src/main/bip/Robot.bip:" + (use + 1) + ":" + column
                + ": error: package Warehouse not found: add -I "
                + "<folder holding Warehouse.bip> (Maven: a <modelPath> entry), or name its file; the model path is ["
                + B + "robot/src/main/bip]\n")
                .containsPattern("\nbip: 1 error\\(s\\), 0 warning\\(s\\) \\(and [1-9][0-9]* unknown name\\(s\\) in "
                        + "packages that use a package not found, not shown\\)\n$");
        assertThat(out.toString(StandardCharsets.UTF_8)).isEmpty();
    }

    @Test
    void aPackageMissingForSeveralFilesIsReportedOnce() throws Exception {
        Files.writeString(dir.resolve("A.bip"), "package A\n  use Gone\n  atom type X()\n    port Gone.T p()\n"
                + "    place S\n    initial to S\n  end\nend\n");
        Files.writeString(dir.resolve("B.bip"), "package B\n  use Gone\n  use A\nend\n");
        assertThat(run("check", dir.resolve("A.bip").toString(), dir.resolve("B.bip").toString())).isEqualTo(1);
        assertThat(err()).containsOnlyOnce("package Gone not found").contains("bip: 1 error(s)");
    }

    @Test
    void generateSaysWhatItWroteWhatNotWhyAndWhichFlagsWould() {
        Path gen = dir.resolve("gen");
        assertThat(run("generate", B + "robot/src/main/bip/Robot.bip", "-I", B + "events/src/main/bip", "-o",
                gen.toString())).as(err()).isZero();
        assertThat(out.toString(StandardCharsets.UTF_8)).isEqualTo("bip: wrote 2 Java file(s) to " + gen + ":\n"
                + "  Robot_behavior: eu.brain.iot.behaviours.robot.RobotBehavior (atom class), RobotBehaviorExterns "
                + "(its extern functions: implement this interface)\n"
                + "  no behaviour class for Robot_behavior: no root compound instantiates it (the files given declare "
                + "no compound type and --root names none)\n"
                + "  no event types: they are generated with the root compound\n"
                + "  to generate the behaviour of Robot_behavior: give --root WarehouseSystem.Compound (in " + B
                + "events/src/main/bip/WarehouseSystem.bip) and -I for the folder of every package it uses\n");

        // following the hint: the behaviour, and why the event types are not here
        out.reset();
        assertThat(run("generate", B + "robot/src/main/bip/Robot.bip", "-I", B + "events/src/main/bip", "-I",
                B + "door/src/main/bip", "-I", B + "orchestrator/src/main/bip", "--root", "WarehouseSystem.Compound",
                "-o", gen.toString())).as(err()).isZero();
        assertThat(out.toString(StandardCharsets.UTF_8)).contains("bip: wrote 3 Java file(s)")
                .contains("  Robot_behavior: eu.brain.iot.behaviours.robot.RobotSmartBehaviour (smart behaviour "
                        + "hosting Robot1, Robot2, Robot3 of WarehouseSystem.Compound, one copy per group)\n")
                .contains("  no event types: they belong to the root compound's package WarehouseSystem");
        assertThat(gen.resolve("eu/brain/iot/behaviours/robot/RobotSmartBehaviour.java")).exists();
    }

    @Test
    void helpIsTheUsageOnStdoutWithZeroAndNoCommandTheUsageOnStderrWithTwo() {
        assertThat(run("-h")).isZero();
        assertThat(run("--help")).isZero();
        assertThat(out.toString(StandardCharsets.UTF_8)).isEqualTo(Main.USAGE + Main.USAGE);
        assertThat(err()).isEmpty();
        assertThat(run()).isEqualTo(2);
        assertThat(err()).isEqualTo(Main.USAGE);
    }

    @Test
    void eachBadCommandLineSaysWhatIsWrongThenTheUsage() {
        String[][] cases = {
            {"bip: unknown command frobnicate", "frobnicate", "x.bip"},
            {"bip: unknown option --bogus", "check", "--bogus", "x.bip"},
            {"bip: unknown option -q", "print", "x.bip", "-q"},
            {"bip: -I needs a value", "check", "x.bip", "-I"},
            {"bip: -o needs a value", "generate", "x.bip", "-o"},
            {"bip: --root needs a value", "check", "x.bip", "--root"},
            {"bip: no model file given", "check"},
            {"bip: no model file given", "print", "-I", "models"},
            {"bip: generate needs -o DIR", "generate", "x.bip"},
        };
        for (String[] c : cases) {
            err.reset();
            String[] args = java.util.Arrays.copyOfRange(c, 1, c.length);
            assertThat(run(args)).as(String.join(" ", args)).isEqualTo(2);
            assertThat(err()).as(String.join(" ", args)).isEqualTo(c[0] + "\n" + Main.USAGE + "\n");
        }
        assertThat(out.toString(StandardCharsets.UTF_8)).isEmpty();
    }

    @Test
    void optionsMayFollowTheFilesAndAnOptionGivenTwiceTakesTheLastValue() throws Exception {
        Path model = dir.resolve("Ok.bip");
        Files.writeString(model, "package Ok\n  port type P()\n  atom type A()\n    port P p()\n    place S\n"
                + "    initial to S\n    on p from S to S\n  end\n  compound type C()\n    component A a()\n  end\nend\n");
        assertThat(run("check", "--root", "Nope", model.toString(), "--root", "C", "-I", dir.toString())).as(err())
                .isZero();
        assertThat(out.toString(StandardCharsets.UTF_8)).isEqualTo("bip: 1 file(s) checked, no errors\n");
        out.reset();
        assertThat(run("print", model.toString())).isZero();
        assertThat(out.toString(StandardCharsets.UTF_8)).startsWith("package Ok\n");
    }
}
