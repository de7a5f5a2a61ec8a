package eu.brain.iot.behaviours.robot.impl;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.InputStream;
import java.lang.reflect.Proxy;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;

import javax.xml.parsers.DocumentBuilderFactory;

import org.junit.jupiter.api.Test;
import org.w3c.dom.Element;
import org.w3c.dom.NodeList;

import eu.brain.iot.edge.api.CommandOutcome;
import eu.brain.iot.edge.api.DeviceRecovered;
import eu.brain.iot.edge.api.DeviceUnreachable;
import eu.brain.iot.edge.api.MissionFailed;
import eu.brain.iot.edge.api.MissionFinished;
import eu.brain.iot.edge.api.ObstacleCleared;
import eu.brain.iot.edge.api.ObstacleDetected;
import eu.brain.iot.edge.api.RobotPositionChanged;
import eu.brain.iot.eventing.annotation.SmartBehaviourNamespace;
import eu.brain.iot.eventing.api.BrainIoTEvent;

/**
 * The robot binding's consumed event types and its inputs are declared in one place: a type added to the
 * {@code @SmartBehaviourDefinition(consumed = ...)} list but not to {@link RobotBinding#INPUTS}, or the other way
 * round, fails here.
 */
class RobotInputTest {

    @Test
    void theTableHoldsExactlyTheConsumedTypes() throws Exception {
        assertThat(RobotBinding.INPUTS.types().stream().map(Class::getName))
                .containsExactlyInAnyOrderElementsOf(consumed(RobotBinding.class));
    }

    @Test
    void everyConsumedEventBecomesAnInputOfItsKind() throws Exception {
        Map<Class<?>, String> handledBy = Map.of(RobotPositionChanged.class, "moved", ObstacleDetected.class,
                "obstacle", ObstacleCleared.class, "obstacle", MissionFinished.class, "missionEnded",
                MissionFailed.class, "missionEnded", CommandOutcome.class, "outcome", DeviceUnreachable.class,
                "unreachable", DeviceRecovered.class, "recovered", RobotModelReport.class, "reported");
        for (String name : consumed(RobotBinding.class)) {
            BrainIoTEvent event = (BrainIoTEvent) Class.forName(name).getConstructor().newInstance();
            assertThat(handledBy(RobotBinding.INPUTS.inputOf(event))).as(name)
                    .containsExactly(handledBy.get(event.getClass()));
        }
    }

    @Test
    void inputsCarryWhatTheBindingThreadNeeds() {
        MissionFailed failed = new MissionFailed();
        failed.robotId = "robot4";
        failed.missionType = "goto";
        failed.goalX = 3;
        failed.goalY = 7;
        failed.reason = "no path";
        assertThat(RobotBinding.INPUTS.inputOf(failed))
                .isEqualTo(new RobotInput.MissionEnded("robot4", "goto", 3, 7, true, "no path"));
        MissionFinished finished = new MissionFinished();
        finished.robotId = "robot4";
        finished.missionType = "pick";
        assertThat(RobotBinding.INPUTS.inputOf(finished))
                .isEqualTo(new RobotInput.MissionEnded("robot4", "pick", null, null, false, null));
        RobotPositionChanged moved = new RobotPositionChanged();
        moved.robotId = "robot5";
        moved.previousX = 3;
        moved.previousY = 4;
        assertThat(RobotBinding.INPUTS.inputOf(moved)).isEqualTo(new RobotInput.Moved("robot5", false));
        moved.previousX = null; // discovered, or taken over by the node that polls it now
        moved.previousY = null;
        assertThat(RobotBinding.INPUTS.inputOf(moved)).isEqualTo(new RobotInput.Moved("robot5", true));
        ObstacleCleared cleared = new ObstacleCleared();
        cleared.robotId = "robot2";
        assertThat(RobotBinding.INPUTS.inputOf(cleared)).isEqualTo(new RobotInput.Obstacle("robot2", true));
        DeviceRecovered recovered = new DeviceRecovered();
        recovered.deviceId = "door1";
        recovered.deviceKind = "door";
        recovered.downMillis = 1200;
        assertThat(RobotBinding.INPUTS.inputOf(recovered)).isEqualTo(new RobotInput.Recovered("door1", "door", 1200));
        // the bus delivers the consumed types' subtypes too
        CommandOutcome outcome = new CommandOutcome() {
        };
        assertThat(RobotBinding.INPUTS.inputOf(outcome)).isEqualTo(new RobotInput.Outcome(outcome));
        assertThat(RobotBinding.INPUTS.inputOf(new BrainIoTEvent() {
        })).isNull();
    }

    /** @return the names of the handler's methods the input calls, in order */
    private static List<String> handledBy(RobotInput input) {
        List<String> calls = new ArrayList<>();
        input.handle((RobotInput.Handler) Proxy.newProxyInstance(RobotInput.Handler.class.getClassLoader(),
                new Class<?>[] { RobotInput.Handler.class }, (proxy, method, args) -> {
                    calls.add(method.getName());
                    return null;
                }));
        return calls;
    }

    /**
     * @return the consumed event type names of the component, as the bus reads them: the service property bnd made
     *         of its {@code @SmartBehaviourDefinition} (whose retention is CLASS: reflection does not see it)
     */
    static List<String> consumed(Class<?> component) throws Exception {
        String descriptor = "/OSGI-INF/" + component.getName() + ".xml";
        try (InputStream in = component.getResourceAsStream(descriptor)) {
            assertThat(in).as(descriptor + " (written by bnd-maven-plugin at process-classes)").isNotNull();
            NodeList properties = DocumentBuilderFactory.newInstance().newDocumentBuilder().parse(in)
                    .getElementsByTagName("property");
            for (int i = 0; i < properties.getLength(); i++) {
                Element p = (Element) properties.item(i);
                if (SmartBehaviourNamespace.CONSUMED_PROPERTY.equals(p.getAttribute("name"))) {
                    String value = p.hasAttribute("value") ? p.getAttribute("value") : p.getTextContent();
                    return Arrays.stream(value.split("\n")).map(String::trim).filter(s -> !s.isEmpty()).toList();
                }
            }
        }
        throw new AssertionError(descriptor + " has no property " + SmartBehaviourNamespace.CONSUMED_PROPERTY);
    }
}
