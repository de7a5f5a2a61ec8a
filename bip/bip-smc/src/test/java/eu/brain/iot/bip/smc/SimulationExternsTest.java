package eu.brain.iot.bip.smc;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import eu.brain.iot.bip.diag.Diagnostics;
import eu.brain.iot.bip.smc.engine.PointResult;
import eu.brain.iot.bip.smc.runtime.SimulatedSystem;
import eu.brain.iot.bip.smc.runtime.TraceRandom;
import eu.brain.iot.bip.smc.sim.SystemSimulator;

/** Extern functions simulated by a class named beside the model, in both engines and through a requirements file. */
class SimulationExternsTest {

    @Test
    void aRequirementsFileNamesTheSimulationOfTheExterns(@TempDir Path dir) throws Exception {
        Path requirements = dir.resolve("requirements.smc");
        // P(some of 3 readings is 1) = 1 - 0.75^3 = 0.578125
        Files.writeString(requirements, """
                set externs = eu.brain.iot.bip.smc.SensorSimulation
                set epsilon = 0.02
                hit: P=? [ F<=10 s.v == 1 ]
                REQ: P>=0.5 [ F<=10 s.v == 1 ]
                """);
        Diagnostics d = new Diagnostics();
        RequirementsCheck.Outcome o = RequirementsCheck.run(new RequirementsCheck.Request(
                List.of(SmcModels.DIR.resolve("Sensor.bip")), List.of(), null, requirements, dir.resolve("out"),
                Map.of("threads", "2"), List.of()), d, null).orElseThrow(() -> new AssertionError(d.toString()));
        PointResult hit = o.results().get(0);
        assertThat(hit.estimate()).isCloseTo(1 - Math.pow(0.75, 3), org.assertj.core.data.Offset.offset(0.02));
        assertThat(o.refuted()).isEmpty();
        assertThat(Files.readString(dir.resolve("out/report.csv"))).contains("\"hit\"");
    }

    @Test
    void aMissingSimulationClassIsReportedAtItsLine(@TempDir Path dir) throws Exception {
        Path requirements = dir.resolve("requirements.smc");
        Files.writeString(requirements, "\nset externs = com.example.Missing\nhit: P=? [ F<=10 s.v == 1 ]\n");
        Diagnostics d = new Diagnostics();
        assertThat(RequirementsCheck.run(new RequirementsCheck.Request(List.of(SmcModels.DIR.resolve("Sensor.bip")),
                List.of(), null, requirements, null, Map.of(), List.of()), d, null)).isEmpty();
        assertThat(d.errors()).singleElement().asString().contains("requirements.smc:2:1: error: class "
                + "com.example.Missing not found");
    }

    @Test
    void bothEnginesCallTheSimulationAlike() throws Exception {
        SmcSession s = SmcModels.load("Sensor");
        var q = s.parse("P=? [ F<=10 s.v == 1 ]");
        SimulatedSystem c = SystemSimulator.of(s.system(), List.of(q), SystemSimulator.Engine.COMPILED,
                SensorSimulation::new, List.of()).create(0, new double[0]);
        SimulatedSystem i = SystemSimulator.of(s.system(), List.of(q), SystemSimulator.Engine.INTERPRETED,
                SensorSimulation::new, List.of()).create(0, new double[0]);
        for (int t = 0; t < 50; t++) {
            c.reset(TraceRandom.traceSeed(3, t));
            i.reset(TraceRandom.traceSeed(3, t));
            while (c.step() & i.step()) {
                assertThat(c.state()).isEqualTo(i.state());
            }
            assertThat(c.state()).isEqualTo(i.state());
        }
    }
}
