package eu.brain.iot.bip.generate;

import static org.assertj.core.api.Assertions.assertThat;

import java.lang.reflect.Field;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import eu.brain.iot.bip.Models;
import eu.brain.iot.bip.Mutants;
import eu.brain.iot.bip.Toolchain;
import eu.brain.iot.bip.check.PackageScope;
import eu.brain.iot.bip.check.Workspace;
import eu.brain.iot.bip.diag.Diagnostics;
import eu.brain.iot.bip.interp.AtomRun;
import eu.brain.iot.bip.model.AtomType;
import eu.brain.iot.bip.model.BipPackage;
import eu.brain.iot.bip.model.DataDecl;

/**
 * What {@code check} accepts, {@code generate} turns into Java that compiles (javac -Werror): every form of constant,
 * the later BIP2 constructs in a whole system, and mutated models that still check.
 */
class CheckedModelsCompileTest {

    /**
     * How many checking mutants are generated and compiled: each compile takes a few hundred milliseconds, so CI
     * compiles 12; {@code -Dbip.mutants=500} searches further.
     */
    private static final int COMPILED_MUTANTS = Integer.getInteger("bip.mutants", 12);

    @TempDir
    Path out;

    @Test
    void everyFormOfConstantCompilesWithItsValue() throws Exception {
        Toolchain tool = Models.check("Consts.bip", Models.resource("models/Consts.bip"), "Other.bip",
                Models.resource("models/Other.bip"));
        assertThat(tool.diagnostics().errors()).isEmpty();
        List<JavaFile> files = tool.generateInMemory("Consts.Top");
        assertThat(tool.diagnostics().errors()).isEmpty();
        ClassLoader loader = InMemoryCompiler.compile(files, out);
        Class<?> user = loader.loadClass("consts.User");
        assertThat(staticValue(user, "K_C")).isEqualTo(25);
        assertThat(staticValue(user, "K_Min")).isEqualTo(Integer.MIN_VALUE);
        assertThat(staticValue(user, "K_Big")).isEqualTo(Double.POSITIVE_INFINITY);
        assertThat(staticValue(user, "K_FromOther")).isEqualTo(8);
        assertThat(staticValue(user, "K_Other_Y")).isEqualTo(4);
        assertThat(staticValue(user, "K_S")).isEqualTo("c=25");

        BipPackage pkg = tool.workspace().ownPackages().stream().filter(p -> p.name().equals("Consts")).findFirst()
                .orElseThrow();
        AtomType atom = pkg.atomTypes().get(0);
        AtomRun interpreted = new AtomRun(atom, new PackageScope(tool.workspace(), pkg), List.of(25),
                (name, types, result, args) -> null);
        Object generated = user.getConstructors()[0].newInstance(25);
        Map<String, Object> expected = new LinkedHashMap<>();
        for (DataDecl d : atom.data()) {
            expected.put(d.name(), interpreted.get(d.name()));
        }
        assertThat(user.getMethod("data").invoke(generated)).isEqualTo(expected);
        assertThat(expected).containsEntry("a", 25).containsEntry("o", 12).containsEntry("s", "c=25");
    }

    @Test
    void laterBip2SystemCompiles() {
        Toolchain tool = Models.check("Later.bip", Models.resource("golden/bip2.bip"), "Plant.bip",
                Models.resource("models/Plant.bip"));
        assertThat(tool.diagnostics().errors()).isEmpty();
        List<JavaFile> files = tool.generateInMemory("Plant.Top");
        assertThat(tool.diagnostics().errors()).isEmpty();
        assertThat(files).extracting(JavaFile::className).contains("Sensor", "SensorBehaviour", "SensorSample",
                "SensorReset", "SensorFault", "SensorPlain");
        String behaviour = files.stream().filter(f -> f.className().equals("SensorBehaviour")).findFirst()
                .orElseThrow().source();
        assertThat(behaviour).contains("replaySample", "policy error", "checkInvariants").doesNotContain(
                "replayReset");
        InMemoryCompiler.compile(files, out);
    }

    @ParameterizedTest
    @ValueSource(strings = {"Ext", "Real"})
    void modelsInTheStyleOfVerimagExamplesCompile(String name) {
        Toolchain tool = Models.check(name + ".bip", Models.resource("models/" + name + ".bip"));
        assertThat(tool.diagnostics().errors()).isEmpty();
        List<JavaFile> files = tool.generateInMemory(null);
        assertThat(tool.diagnostics().errors()).isEmpty();
        InMemoryCompiler.compile(files, out);
    }

    @Test
    void mutantsThatCheckAlsoCompile() {
        List<String> seeds = Mutants.seeds();
        Random random = new Random(20_261_123);
        int compiled = 0;
        for (int i = 0; i < 400 * COMPILED_MUTANTS && compiled < COMPILED_MUTANTS; i++) {
            String model = Mutants.mutate(seeds.get(random.nextInt(seeds.size())), random);
            Workspace ws = new Workspace(List.of(), new Diagnostics());
            ws.addSource("mutant" + i + ".bip", model);
            ws.resolveUses();
            Toolchain tool = Toolchain.of(ws);
            if (!tool.check()) {
                continue;
            }
            List<JavaFile> files = tool.generateInMemory(null);
            if (!tool.diagnostics().errors().isEmpty() || files.isEmpty()) {
                continue; // a system the bus cannot realise (reported), or a package of declarations only
            }
            try {
                InMemoryCompiler.compile(files, out.resolve("m" + i));
            } catch (AssertionError e) {
                throw new AssertionError("mutant " + i + " checks but its Java does not compile:\n" + model, e);
            }
            compiled++;
        }
        assertThat(compiled).isEqualTo(COMPILED_MUTANTS);
    }

    private static Object staticValue(Class<?> type, String name) throws ReflectiveOperationException {
        Field f = type.getDeclaredField(name);
        f.setAccessible(true);
        return f.get(null);
    }
}
