package eu.brain.iot.bip.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

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
        assertThat(output.resolve("eu/brain/iot/behaviours/robot/RobotBehaviorBehaviour.java")).exists();
        assertThat(output.resolve("eu/brain/iot/behaviours/events/ConnectorResolveCollision.java")).exists();
        // 20: the collision-resolved connector is a broadcast since issue 13 (no offer event of its own)
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
        assertThat(err()).contains(model + ":2:3: error: package Missing not found: no Missing.bip in the model path");
    }
}
