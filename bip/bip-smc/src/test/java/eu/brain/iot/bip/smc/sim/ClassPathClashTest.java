package eu.brain.iot.bip.smc.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import eu.brain.iot.bip.diag.Diagnostics;
import eu.brain.iot.bip.generate.JavaFile;
import eu.brain.iot.bip.generate.SimulationWriter;
import eu.brain.iot.bip.smc.SmcSession;
import eu.brain.iot.bip.smc.engine.SmcOptions;
import eu.brain.iot.bip.smc.engine.SmcRunner;
import eu.brain.iot.bip.smc.engine.TraceFailureException;
import eu.brain.iot.bip.smc.query.Query;
import eu.brain.iot.bip.smc.runtime.Builtins;
import eu.brain.iot.bip.smc.runtime.SimulatedSystem;
import eu.brain.iot.bip.smc.runtime.SimulationExterns;
import eu.brain.iot.bip.smc.runtime.TraceRandom;

/**
 * The compiled engine when the class path it runs on already holds classes of the names it compiles, as a test or
 * the Maven goal does with the deployed behaviour jars as dependencies: the compiled classes are the ones that run
 * (the parent's would differ, or fail with IllegalAccessError across runtime packages), and a class of the parent
 * that does not link with the compiled code fails the run at once, saying so, instead of killing a sampling thread
 * and leaving the run waiting for ever.
 */
class ClassPathClashTest {

    private static final Path WALK = Path.of("src/test/resources/smc/RandomWalk.bip");

    private static SmcSession load(Path file) {
        Diagnostics d = new Diagnostics();
        return SmcSession.load(List.of(file), List.of(), null, d)
                .orElseThrow(() -> new AssertionError("model does not check: " + d));
    }

    /**
     * A class loader holding what a deployed jar of {@code model} holds: its atom classes and extern interfaces
     * (the bridges and extern simulations are the model checker's own), over the model checker's loader.
     */
    private static ClassLoader deployedJar(SmcSession model) throws Exception {
        List<JavaFile> deployed = new SimulationWriter(model.system(), new Diagnostics(), Builtins::isBuiltin).atomFiles().stream()
                .filter(f -> !f.qualifiedName().endsWith("Smc") && !f.qualifiedName().endsWith("SmcExterns"))
                .toList();
        assertThat(deployed).extracting(JavaFile::qualifiedName).contains("randomwalk.Walker");
        return RuntimeCompiler.compile(deployed, List.of());
    }

    @Test
    void theCompiledClassesRunEvenWhenTheParentHoldsAnotherVersionOfThem(@TempDir Path dir) throws Exception {
        // the "deployed" Walker is an older version of the model: it steps by 2
        Path stale = dir.resolve("RandomWalk.bip");
        String text = Files.readString(WALK);
        Files.writeString(stale, text.replace("x = x + 1", "x = x + 2"));
        assertThat(Files.readString(stale)).isNotEqualTo(text);
        ClassLoader parent = deployedJar(load(stale));
        assertThat(parent.loadClass("randomwalk.Walker").getClassLoader()).as("the clash is real").isSameAs(parent);

        SmcSession model = load(WALK);
        Query q = model.parse("P=? [ F<=100 w.x == 6 ]");
        SimulatedSystem compiled = SystemSimulator.of(model.system(), List.of(q), SystemSimulator.Engine.COMPILED,
                () -> SimulationExterns.NONE, List.of(), parent).create(0, new double[0]);
        SimulatedSystem reference = SystemSimulator.of(model.system(), List.of(q), SystemSimulator.Engine.INTERPRETED,
                () -> SimulationExterns.NONE, List.of()).create(0, new double[0]);
        int steps = 0;
        for (int trace = 0; trace < 40; trace++) {
            compiled.reset(TraceRandom.traceSeed(5, trace));
            reference.reset(TraceRandom.traceSeed(5, trace));
            while (compiled.step() & reference.step()) {
                steps++;
                assertThat(compiled.state()).as("trace %d after %s", trace, compiled.lastStep())
                        .isEqualTo(reference.state());
            }
            assertThat(compiled.state()).isEqualTo(reference.state());
        }
        assertThat(steps).as("the walks move").isGreaterThan(100);

        // and through the sampling threads: the gambler's ruin from 3 of 6 with p = 0.4 (see RandomWalk.bip)
        double r = 0.6 / 0.4;
        double exact = (1 - Math.pow(r, 3)) / (1 - Math.pow(r, 6));
        SmcOptions options = SmcOptions.defaults().withThreads(2).with("epsilon", "0.02");
        SystemSimulator simulator = SystemSimulator.of(model.system(), List.of(q), SystemSimulator.Engine.COMPILED,
                () -> SimulationExterns.NONE, List.of(), parent);
        double estimate = assertTimeoutPreemptively(Duration.ofMinutes(1),
                () -> new SmcRunner(simulator, List.of(q), options).run(0, null).get(0).estimate());
        assertThat(estimate).isCloseTo(exact, org.assertj.core.data.Offset.offset(0.02));
    }

    @Test
    void aParentClassThatDoesNotLinkWithTheCompiledCodeFailsTheRunAtOnce() throws Exception {
        // a stale copy of a class bip's runtime gives the compiled code (it lacks the methods the driver calls)
        ClassLoader parent = RuntimeCompiler.compile(List.of(new JavaFile("eu.brain.iot.bip.smc.runtime",
                "TraceRandom", "package eu.brain.iot.bip.smc.runtime; public final class TraceRandom { }")), List.of());
        SmcSession model = load(WALK);
        Query q = model.parse("P=? [ F<=100 w.x == 6 ]");
        SystemSimulator simulator = SystemSimulator.of(model.system(), List.of(q), SystemSimulator.Engine.COMPILED,
                () -> SimulationExterns.NONE, List.of(), parent);
        SmcOptions options = SmcOptions.defaults().withThreads(2);
        assertTimeoutPreemptively(Duration.ofSeconds(60), () -> assertThatThrownBy(
                () -> new SmcRunner(simulator, List.of(q), options).run(0, null))
                .isInstanceOf(TraceFailureException.class)
                .hasMessageStartingWith("trace 0 (seed 1) failed in its initial state: the Java compiled for "
                        + "the model failed to link (java.lang.NoSuchMethodError")
                .hasMessageContaining("please report it with the model; '--engine interpreted' checks the same query"));
    }
}
