package eu.brain.iot.behaviours.system.sim;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

import eu.brain.iot.bip.check.ModelSet;
import eu.brain.iot.bip.diag.Diagnostics;
import eu.brain.iot.bip.model.BipPackage;
import eu.brain.iot.bip.model.ExternFunction;
import eu.brain.iot.bip.model.Param;
import eu.brain.iot.bip.smc.runtime.Builtins;
import eu.brain.iot.bip.smc.runtime.TraceRandom;

/**
 * A model that grows keeps its gate: every extern function that the closed system's models declare (the deployed
 * Robot.bip, Door.bip, Orchestrator.bip and the environment) has a simulation in {@link WarehouseSimulation} that
 * answers a value of the declared type. Fails, naming the function and its model, when a model gains an extern
 * function nobody simulated (the gate would fail later, in the middle of sampling).
 */
class SimulationCoversModelsTest {

    private static final Path BEHAVIOURS = Path.of("..");

    @Test
    void everyExternFunctionOfTheClosedSystemIsSimulated() {
        Diagnostics diagnostics = new Diagnostics();
        ModelSet models = ModelSet.load(List.of(Path.of("src/main/bip/WarehouseEnvironment.bip")),
                List.of(BEHAVIOURS.resolve("events/src/main/bip"), BEHAVIOURS.resolve("robot/src/main/bip"),
                        BEHAVIOURS.resolve("door/src/main/bip"), BEHAVIOURS.resolve("orchestrator/src/main/bip")),
                diagnostics);
        assertThat(models.check()).as("the closed system checks: %s", diagnostics.sorted()).isTrue();

        WarehouseSimulation simulation = new WarehouseSimulation();
        TraceRandom random = new TraceRandom();
        random.seed(1);
        List<String> functions = new ArrayList<>();
        for (BipPackage pkg : models.workspace().packages()) {
            for (ExternFunction f : pkg.externFunctions()) {
                List<String> types = f.params().stream().map(p -> p.type().name()).toList();
                String result = f.returnType() == null ? "no value" : f.returnType().name();
                if (Builtins.isBuiltin(f.name(), types, result)) {
                    continue;
                }
                functions.add(pkg.name() + "." + f.name());
                assertThat(simulation.simulates(f.name()))
                        .as("extern function %s of %s (%s) has a simulation", f.name(), pkg.name(), f.pos())
                        .isTrue();
                Object value = simulation.call(f.name(), types, result, arguments(f.params()), random);
                switch (result) {
                    case "no value" -> assertThat(value).as(f.name()).isNull();
                    case "int" -> assertThat(value).as(f.name()).isInstanceOf(Integer.class);
                    case "float", "double" -> assertThat(value).as(f.name()).isInstanceOf(Double.class);
                    case "bool" -> assertThat(value).as(f.name()).isInstanceOf(Boolean.class);
                    default -> assertThat(value).as(f.name()).isNotNull();
                }
            }
        }
        assertThat(functions).contains("Robot.getPosition", "Robot.liftCart", "Robot.moveTo", "Door.open",
                "Orchestrator.resolvedPosition1", "Orchestrator.resolvedPosition2", "Orchestrator.resolvedPosition3");
    }

    private static Object[] arguments(List<Param> params) {
        return params.stream().map(p -> switch (p.type().name()) {
            case "int" -> (Object) 3;
            case "float", "double" -> (Object) 2.0;
            case "bool" -> (Object) Boolean.TRUE;
            default -> (Object) "";
        }).toArray();
    }
}
