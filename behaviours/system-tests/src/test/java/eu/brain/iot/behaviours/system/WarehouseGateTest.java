package eu.brain.iot.behaviours.system;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import eu.brain.iot.behaviours.orchestrator.impl.OrchestratorExterns;
import eu.brain.iot.behaviours.system.sim.WarehouseSimulation;
import eu.brain.iot.bip.cli.Main;

/**
 * The warehouse gate refutes on the real system, not only on toy models: REQ-2 as requirements.smc states it, but
 * demanded with probability 0.95, is refuted on today's deployed models (the orchestrator resolves a robot-in-front
 * detection only when all three robots are stopped, so robots are stranded in about 23% of the runs; see
 * behaviours/README.md), and `bip smc` exits 1 naming it. When this test fails because REQ-2 now holds at 0.95, the
 * defect is fixed: raise REQ-2's threshold in requirements.smc.
 * <p>
 * Runs the command line in a JVM of its own: this test's class path holds the deployed behaviour classes, which the
 * compiled engine generates again under the same names.
 */
class WarehouseGateTest {

    private static final Path REQUIREMENTS = Path.of("src/main/bip/requirements.smc");

    @Test
    void req2DemandedAt95PercentIsRefutedOnTheDeployedModels(@TempDir Path dir) throws Exception {
        List<String> strict = Files.readAllLines(REQUIREMENTS).stream()
                .filter(l -> !l.startsWith("REQ-1"))
                .map(l -> l.startsWith("REQ-2:") ? l.replace("P>=0.7 [", "P>=0.95 [") : l)
                .toList();
        assertThat(strict).as("requirements.smc states REQ-2 at 0.7").anyMatch(l -> l.startsWith("REQ-2: P>=0.95 ["));
        Path file = dir.resolve("strict.smc");
        Files.write(file, strict);

        List<String> command = new ArrayList<>(List.of(ProcessHandle.current().info().command().orElse("java"),
                "-cp", location(Main.class), Main.class.getName(), "smc", "src/main/bip/WarehouseEnvironment.bip"));
        for (String model : List.of("events", "robot", "door", "orchestrator")) {
            command.addAll(List.of("-I", "../" + model + "/src/main/bip"));
        }
        command.addAll(List.of("--properties", file.toString(), "--threads", "2", "--quiet",
                "--cp", location(WarehouseSimulation.class) + File.pathSeparator + location(OrchestratorExterns.class)));
        Process bip = new ProcessBuilder(command).redirectOutput(dir.resolve("out.txt").toFile())
                .redirectError(dir.resolve("err.txt").toFile()).start();
        boolean ended = bip.waitFor(3, TimeUnit.MINUTES);
        if (!ended) {
            bip.destroyForcibly();
        }
        String out = Files.readString(dir.resolve("out.txt"), StandardCharsets.UTF_8);
        String err = Files.readString(dir.resolve("err.txt"), StandardCharsets.UTF_8);
        assertThat(ended).as("bip smc ended within 3 minutes; stderr: %s", err).isTrue();
        assertThat(bip.exitValue()).as("exit code; stdout: %s stderr: %s", out, err).isEqualTo(1);
        assertThat(err).contains("1 requirement(s) refuted");
        assertThat(out).containsPattern("REQ-2 +0\\.[0-8]\\d+ .*REFUTED").contains("requirement REQ-2 REFUTED");
    }

    private static String location(Class<?> type) throws Exception {
        return Path.of(type.getProtectionDomain().getCodeSource().getLocation().toURI()).toString();
    }
}
