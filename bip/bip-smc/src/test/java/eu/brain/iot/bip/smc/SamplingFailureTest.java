package eu.brain.iot.bip.smc;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.function.Supplier;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import eu.brain.iot.bip.smc.engine.SmcOptions;
import eu.brain.iot.bip.smc.engine.SmcRunner;
import eu.brain.iot.bip.smc.engine.TraceFailureException;
import eu.brain.iot.bip.smc.query.Query;
import eu.brain.iot.bip.smc.runtime.SimulationExterns;
import eu.brain.iot.bip.smc.runtime.TraceRandom;
import eu.brain.iot.bip.smc.sim.SystemSimulator;

/**
 * A failure in a sampling thread (the simulation of an extern function throws or answers the wrong type, the model's
 * code divides by zero, the simulated system cannot be created) fails the whole run promptly with one message saying
 * which trace, what went wrong and what to do; never a hang, never a dead thread. The failing trace depends on the
 * seed only: the same for any thread count and both engines.
 */
class SamplingFailureTest {

    private static final Duration PROMPT = Duration.ofSeconds(60);

    /** Sensor.bip's read(7), unplugged now and then: throws on about 1 call in 200 (drawn from the trace's random). */
    public static final class FlakySensor implements SimulationExterns {
        @Override
        public Object call(String name, List<String> types, String result, Object[] args, TraceRandom random) {
            if (random.uniform(0, 199) == 0) {
                throw new IllegalStateException("sensor " + args[0] + " unplugged");
            }
            return random.bernoulli(0.25) ? 1 : 0;
        }
    }

    private static TraceFailureException failure(SmcSession s, String query, Supplier<SimulationExterns> externs,
            SystemSimulator.Engine engine, int threads) throws Exception {
        Query q = s.parse(query);
        SmcOptions options = SmcOptions.defaults().withThreads(threads).withEngine(engine);
        SystemSimulator simulator = SystemSimulator.of(s.system(), List.of(q), engine, externs, List.of());
        return assertTimeoutPreemptively(PROMPT, () -> catchThrowableOfType(
                () -> new SmcRunner(simulator, List.of(q), options).run(0, null), TraceFailureException.class));
    }

    @Test
    void anExternSimulationThatThrowsFailsTheRunNamingTheTraceTheFunctionAndTheClass() throws Exception {
        SmcSession s = SmcModels.load("Sensor");
        String q = "P=? [ F<=10 s.v == 2 ]";
        TraceFailureException e = failure(s, q, FlakySensor::new, SystemSimulator.Engine.COMPILED, 3);
        assertThat(e).as("the run fails").isNotNull();
        assertThat(e.getMessage()).matches("trace (\\d+) \\(seed 1\\) failed at step s\\.sample: the simulation of "
                + "extern function int read\\(int\\) in class eu\\.brain\\.iot\\.bip\\.smc\\.SamplingFailureTest\\$"
                + "FlakySensor threw java\\.lang\\.IllegalStateException: sensor 7 unplugged; fix that class .*"
                + "\\(the same seed gives the same trace again\\)");
        String trace = e.getMessage().replaceAll("^trace (\\d+) .*", "$1");
        assertThat(Long.parseLong(trace)).as("the failing trace is not the first one")
                .isGreaterThan(0);
        assertThat(failure(s, q, FlakySensor::new, SystemSimulator.Engine.COMPILED, 1).getMessage())
                .as("one thread").isEqualTo(e.getMessage());
        assertThat(failure(s, q, FlakySensor::new, SystemSimulator.Engine.INTERPRETED, 2).getMessage())
                .as("the interpreter").isEqualTo(e.getMessage());
    }

    @Test
    void anExternSimulationAnsweringTheWrongTypeIsNamed() throws Exception {
        TraceFailureException e = failure(SmcModels.load("Sensor"), "P=? [ F<=10 s.v == 2 ]",
                () -> (name, types, result, args, random) -> 1.5, SystemSimulator.Engine.COMPILED, 2);
        assertThat(e.getMessage()).startsWith("trace 0 (seed 1) failed at step s.sample: the simulation of extern "
                + "function int read(int) in class ").contains(" answered 1.5 (java.lang.Double) where the model "
                + "declares int; fix that class");
    }

    @Test
    void aDivisionByZeroInTheModelFailsTheRunInBothEnginesAlike(@TempDir Path dir) throws Exception {
        Path model = dir.resolve("Div.bip");
        Files.writeString(model, """
                package Div
                  extern function int uniform(int lo, int hi)
                  port type E()
                  atom type A()
                    data int x = 0
                    data int k = 1
                    port E go()
                    place L
                    initial to L
                    on go from L to L do { k = uniform(0, 30); x = 100 / k; }
                  end
                  compound type Top()
                    component A a()
                  end
                end
                """);
        SmcSession s = SmcModels.load(model);
        String q = "P=? [ F<=5 a.x == 1000 ]";
        TraceFailureException c = failure(s, q, () -> SimulationExterns.NONE, SystemSimulator.Engine.COMPILED, 2);
        TraceFailureException i = failure(s, q, () -> SimulationExterns.NONE, SystemSimulator.Engine.INTERPRETED, 2);
        assertThat(c.getMessage()).matches("trace \\d+ \\(seed 1\\) failed at step a\\.go: the model's code threw "
                + "java\\.lang\\.ArithmeticException: / by zero at .*; correct the model .*");
        assertThat(i.getMessage()).as("the same trace in the interpreter")
                .startsWith(c.getMessage().substring(0, c.getMessage().indexOf(" at step")));
    }

    @Test
    void aSystemThatCannotBeCreatedFailsTheRunAtOnce() throws Exception {
        TraceFailureException e = failure(SmcModels.load("Sensor"), "P=? [ F<=10 s.v == 1 ]", () -> {
            throw new IllegalStateException("no licence for the sensor simulator");
        }, SystemSimulator.Engine.COMPILED, 2);
        assertThat(e.getMessage()).startsWith("the simulated system could not be created: the model's code threw "
                + "java.lang.IllegalStateException: no licence for the sensor simulator");
    }
}
