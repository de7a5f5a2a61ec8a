package eu.brain.iot.bip.generate;

import static org.assertj.core.api.Assertions.assertThat;

import java.lang.reflect.Constructor;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.lang.reflect.Proxy;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.Set;
import java.util.TreeSet;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import eu.brain.iot.bip.Models;
import eu.brain.iot.bip.SyntheticModel;
import eu.brain.iot.bip.check.PackageScope;
import eu.brain.iot.bip.check.Type;
import eu.brain.iot.bip.interp.AtomRun;
import eu.brain.iot.bip.model.AtomType;
import eu.brain.iot.bip.model.BipPackage;
import eu.brain.iot.bip.model.DataDecl;
import eu.brain.iot.bip.model.Param;
import eu.brain.iot.bip.model.PortDecl;

/**
 * The generated Java compiles (javac with -Werror) and, on random sequences of port firings, internal steps and
 * data transfers, every generated atom takes exactly the transitions a direct interpretation of the model takes,
 * ending in the same places with the same data after each step.
 */
class GeneratedCodeTest {

    private static final int STEPS = 300;

    @TempDir
    Path out;

    @Test
    void warehouseCompilesAndMatchesTheInterpreter() throws Exception {
        Toolchain tool = Tools.warehouse();
        List<JavaFile> files = tool.generateInMemory(null);
        assertThat(tool.diagnostics().errors()).isEmpty();
        assertThat(files).extracting(JavaFile::className).contains("RobotBehavior", "RobotBehaviorExterns",
                "RobotSmartBehaviour", "DoorSmartBehaviour", "OrchestratorSmartBehaviour",
                "ConnectorResolveCollision", "ConnectorResolveCollisionOffer", "ConnectorTypeDoor", "TransitionFired");
        compareAll(tool, InMemoryCompiler.compile(files, out));
    }

    @Test
    void languageCornersCompileAndMatchTheInterpreter() throws Exception {
        Toolchain tool = Tools.check("atom.bip", Models.resource("golden/atom.bip"), "bip2.bip",
                Models.resource("golden/bip2.bip"), "expressions.bip",
                Models.resource("golden/expressions.bip").replace("@java(import=\"Map\", src=\"org.map\")", ""),
                "synthetic.bip", SyntheticModel.of(600, 3));
        assertThat(tool.diagnostics().errors()).isEmpty();
        List<JavaFile> files = tool.generateInMemory("Synthetic.Top");
        assertThat(tool.diagnostics().errors()).isEmpty();
        compareAll(tool, InMemoryCompiler.compile(files, out));
    }

    private void compareAll(Toolchain tool, ClassLoader loader) throws Exception {
        int compared = 0;
        for (BipPackage pkg : tool.workspace().ownPackages()) {
            PackageScope scope = new PackageScope(tool.workspace(), pkg);
            for (AtomType atom : pkg.atomTypes()) {
                String javaPackage = JavaNames.javaPackage(pkg);
                Class<?> cls = loader.loadClass(javaPackage + "." + JavaNames.type(atom.name()));
                Class<?> externs = null;
                try {
                    externs = loader.loadClass(javaPackage + "." + JavaNames.type(atom.name()) + "Externs");
                } catch (ClassNotFoundException none) {
                    // this atom calls no extern function
                }
                for (long seed = 1; seed <= 5; seed++) {
                    compare(atom, scope, cls, externs, new Random(seed * 31 + atom.name().hashCode()));
                    compared++;
                }
            }
        }
        assertThat(compared).isGreaterThan(0);
    }

    /** A deterministic stand-in for extern functions: the result depends on the name and arguments only. */
    static Object fake(String name, String resultType, Object[] args) {
        int h = Math.abs((name + Arrays.toString(args)).hashCode());
        return switch (resultType) {
            case "int" -> h % 7;
            case "float" -> (h % 5) * 0.5;
            case "bool" -> h % 2 == 0;
            case "string" -> "s" + h % 3;
            default -> null;
        };
    }

    private static String bipType(Class<?> javaType) {
        if (javaType == int.class) {
            return "int";
        } else if (javaType == double.class) {
            return "float";
        } else if (javaType == boolean.class) {
            return "bool";
        } else if (javaType == String.class) {
            return "string";
        }
        return "none";
    }

    private static Object randomValue(Type t, Random random) {
        return switch (t.kind()) {
            case INT -> random.nextInt(21) - 5;
            case FLOAT -> (random.nextInt(21) - 5) * 0.5;
            case BOOL -> random.nextBoolean();
            case STRING -> "r" + random.nextInt(3);
            default -> null;
        };
    }

    private void compare(AtomType atom, PackageScope scope, Class<?> cls, Class<?> externsType, Random random)
            throws Exception {
        List<Object> args = new ArrayList<>();
        for (Param p : atom.params()) {
            args.add(randomValue(scope.resolveType(p.type().name()), random));
        }
        AtomRun interpreted = new AtomRun(atom, scope, args, (name, types, result, a) -> fake(name, result, a));
        List<Object> ctorArgs = new ArrayList<>();
        if (externsType != null) {
            ctorArgs.add(Proxy.newProxyInstance(cls.getClassLoader(), new Class<?>[] {externsType},
                    (proxy, method, a) -> fake(method.getName(), bipType(method.getReturnType()),
                            a == null ? new Object[0] : a)));
        }
        ctorArgs.addAll(args);
        Constructor<?> ctor = cls.getConstructors()[0];
        Object generated = ctor.newInstance(ctorArgs.toArray());
        assertSameState(atom, interpreted, generated, "after the initial transition");
        Class<?> portEnum = Arrays.stream(cls.getDeclaredClasses()).filter(c -> c.getSimpleName().equals("Port"))
                .findFirst().orElseThrow();
        Method fire = cls.getMethod("fire", portEnum);
        Method internal = cls.getMethod("internalStep");
        Method enabledPorts = cls.getMethod("enabledPorts");
        for (int step = 0; step < STEPS; step++) {
            String what;
            Object expected;
            Object actual;
            int choice = atom.ports().isEmpty() ? 0 : random.nextInt(4);
            if (choice == 0) {
                what = "internal step";
                expected = outcome(interpreted::internalStep);
                actual = outcome(() -> (Boolean) internal.invoke(generated));
            } else {
                PortDecl port = atom.ports().get(random.nextInt(atom.ports().size()));
                if (choice == 1 && !port.boundData().isEmpty()) {
                    // a connector's down transfer writes the port's data before the transition
                    for (String d : port.boundData()) {
                        Object v = randomValue(scope.resolveType(atom.dataDecl(d).orElseThrow().type().name()), random);
                        interpreted.set(d, v);
                        java.lang.reflect.Field field = cls.getDeclaredField(AtomWriter.field(d));
                        field.setAccessible(true);
                        field.set(generated, v);
                    }
                }
                what = "port " + port.name();
                Object constant = enumConstant(portEnum, port.name());
                expected = outcome(() -> interpreted.fire(port.name()));
                actual = outcome(() -> (Boolean) fire.invoke(generated, constant));
            }
            assertThat(actual).as("%s: step %d (%s)", atom.name(), step, what).isEqualTo(expected);
            assertSameState(atom, interpreted, generated, "after step " + step + " (" + what + ")");
            Set<String> enabled = new TreeSet<>();
            ((Set<?>) enabledPorts.invoke(generated)).forEach(p -> enabled.add(((Enum<?>) p).name()));
            assertThat(enabled).as("enabled ports of %s after step %d", atom.name(), step)
                    .isEqualTo(new TreeSet<>(interpreted.enabledPorts()));
        }
    }

    private static Object enumConstant(Class<?> enumType, String name) {
        for (Object c : enumType.getEnumConstants()) {
            if (((Enum<?>) c).name().equals(JavaNames.id(name))) {
                return c;
            }
        }
        throw new IllegalArgumentException(name);
    }

    interface Step {
        Boolean run() throws Exception;
    }

    /** The result of a step, or the kind of exception it threw (e.g. a division by zero). */
    private static Object outcome(Step step) {
        try {
            return step.run();
        } catch (InvocationTargetException e) {
            return e.getCause().getClass().getName();
        } catch (Exception e) {
            return e.getClass().getName();
        }
    }

    private static void assertSameState(AtomType atom, AtomRun interpreted, Object generated, String when)
            throws Exception {
        Set<String> marking = new TreeSet<>();
        ((Set<?>) generated.getClass().getMethod("marking").invoke(generated))
                .forEach(p -> marking.add(((Enum<?>) p).name()));
        assertThat(marking).as("%s places %s", atom.name(), when)
                .isEqualTo(new TreeSet<>(interpreted.marking().stream().map(JavaNames::id).toList()));
        Map<String, Object> expected = new LinkedHashMap<>();
        for (DataDecl d : atom.data()) {
            expected.put(d.name(), interpreted.get(d.name()));
        }
        @SuppressWarnings("unchecked")
        Map<String, Object> actual = (Map<String, Object>) generated.getClass().getMethod("data").invoke(generated);
        assertThat(actual).as("%s data %s", atom.name(), when).isEqualTo(expected);
        Object violated;
        try {
            violated = generated.getClass().getMethod("violatedInvariants").invoke(generated);
        } catch (InvocationTargetException e) {
            violated = e.getCause().getClass().getName();
        }
        Object expectedViolated;
        try {
            expectedViolated = interpreted.violatedInvariants();
        } catch (RuntimeException e) {
            expectedViolated = e.getClass().getName();
        }
        assertThat(violated).as("%s violated invariants %s", atom.name(), when).isEqualTo(expectedViolated);
    }
}
