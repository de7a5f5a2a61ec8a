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
     * compiles 6; {@code -Dbip.mutants=300} searches further (about a minute and a half).
     */
    private static final int COMPILED_MUTANTS = Integer.getInteger("bip.mutants", 6);

    @TempDir
    Path out;

    @Test
    void everyFormOfConstantCompilesWithItsValue() throws Exception {
        Toolchain tool = Tools.check("Consts.bip", Models.resource("models/Consts.bip"), "Other.bip",
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
        Toolchain tool = Tools.check("Later.bip", Models.resource("golden/bip2.bip"), "Plant.bip",
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

    /**
     * The generated behaviour applies an extern port's policy: an event the port cannot take now is remembered and
     * taken (with its data) once the port is enabled, and the behaviour goes on after an event its policy refuses
     * and after an invariant is violated.
     */
    @Test
    void externPortPoliciesOnTheBus() throws Exception {
        Toolchain tool = Tools.check("Later.bip", Models.resource("golden/bip2.bip"), "Solo.bip", """
                package Solo
                  use Later
                  compound type Top()
                    component Later.Sensor s1(1), s2(2)
                  end
                end
                """);
        List<JavaFile> files = tool.generateInMemory("Solo.Top");
        assertThat(tool.diagnostics().errors()).isEmpty();
        ClassLoader loader = InMemoryCompiler.compile(files, out);
        Class<?> externs = loader.loadClass("later.SensorExterns");
        List<Object> published = new java.util.ArrayList<>();
        Object bus = java.lang.reflect.Proxy.newProxyInstance(loader,
                new Class<?>[] {eu.brain.iot.eventing.api.EventBus.class}, (proxy, method, args) -> {
                    published.add(args[0]);
                    return null;
                });
        Object impl = java.lang.reflect.Proxy.newProxyInstance(loader, new Class<?>[] {externs},
                (proxy, method, args) -> method.getName().equals("clamp") ? args[0] : null);
        Object behaviour = loader.loadClass("later.SensorBehaviour").getConstructor(eu.brain.iot.eventing.api.EventBus.class,
                externs, Map.class).newInstance(bus, impl, Map.of());
        java.lang.reflect.Method notify = behaviour.getClass().getMethod("notify",
                eu.brain.iot.eventing.api.BrainIoTEvent.class);
        java.lang.reflect.Method places = behaviour.getClass().getMethod("placesOf", String.class);
        java.lang.reflect.Method data = behaviour.getClass().getMethod("dataOf", String.class);

        notify.invoke(behaviour, event(loader, "solo.SensorReset", "s1", Map.of()));
        assertThat(places.invoke(behaviour, "s1")).as("reset (ignore) at IDLE").isEqualTo(List.of("IDLE"));
        notify.invoke(behaviour, event(loader, "solo.SensorSample", "s1", Map.of("value", 5, "at", 1.0)));
        assertThat(places.invoke(behaviour, "s1")).isEqualTo(List.of("MEASURED"));
        notify.invoke(behaviour, event(loader, "solo.SensorSample", "s1", Map.of("value", 100, "at", 2.0)));
        assertThat(places.invoke(behaviour, "s1")).as("the second sample is remembered").isEqualTo(
                List.of("MEASURED"));
        notify.invoke(behaviour, event(loader, "solo.SensorFault", "s1", Map.of()));
        assertThat(places.invoke(behaviour, "s1")).as("fault (error) refused at MEASURED").isEqualTo(
                List.of("MEASURED"));
        notify.invoke(behaviour, event(loader, "solo.SensorOut", "s1", Map.of()));
        // out: MEASURED -> SENT, internal SENT -> IDLE, then the remembered sample: IDLE -> MEASURED
        assertThat(places.invoke(behaviour, "s1")).isEqualTo(List.of("MEASURED"));
        @SuppressWarnings("unchecked")
        Map<String, Object> s1 = (Map<String, Object>) data.invoke(behaviour, "s1");
        assertThat(s1).containsEntry("level", 100).containsEntry("count", 100).containsEntry("when", 2.0);
        assertThat(places.invoke(behaviour, "s2")).isEqualTo(List.of("IDLE"));
        Class<?> sensor = loader.loadClass("later.Sensor");
        Object atom = sensor.getConstructors()[0].newInstance(impl, 1);
        Field level = sensor.getDeclaredField(AtomWriter.field("count"));
        level.setAccessible(true);
        level.set(atom, 100);
        assertThat(sensor.getMethod("violatedInvariants").invoke(atom)).isEqualTo(List.of("bounded", "idleSmall"));
    }

    private static Object event(ClassLoader loader, String type, String component, Map<String, Object> values)
            throws ReflectiveOperationException {
        Object e = loader.loadClass(type).getConstructor().newInstance();
        e.getClass().getField("component").set(e, component);
        for (Map.Entry<String, Object> v : values.entrySet()) {
            e.getClass().getField(v.getKey()).set(e, v.getValue());
        }
        return e;
    }

    @ParameterizedTest
    @ValueSource(strings = {"Ext", "Real"})
    void modelsInTheStyleOfVerimagExamplesCompile(String name) {
        Toolchain tool = Tools.check(name + ".bip", Models.resource("models/" + name + ".bip"));
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
