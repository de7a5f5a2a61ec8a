package eu.brain.iot.behaviours.door.impl;

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
import eu.brain.iot.edge.api.DoorStateChanged;
import eu.brain.iot.eventing.annotation.SmartBehaviourNamespace;
import eu.brain.iot.eventing.api.BrainIoTEvent;

/**
 * The door binding's consumed event types and its inputs are declared in one place: a type added to the
 * {@code @SmartBehaviourDefinition(consumed = ...)} list but not to {@link DoorBinding#INPUTS}, or the other way
 * round, fails here.
 */
class DoorInputTest {

    @Test
    void theTableHoldsExactlyTheConsumedTypes() throws Exception {
        assertThat(DoorBinding.INPUTS.types().stream().map(Class::getName))
                .containsExactlyInAnyOrderElementsOf(consumed(DoorBinding.class));
    }

    @Test
    void everyConsumedEventBecomesAnInputOfItsKind() throws Exception {
        Map<Class<?>, String> handledBy = Map.of(DoorStateChanged.class, "stateChanged", CommandOutcome.class,
                "outcome");
        for (String name : consumed(DoorBinding.class)) {
            BrainIoTEvent event = (BrainIoTEvent) Class.forName(name).getConstructor().newInstance();
            assertThat(handledBy(DoorBinding.INPUTS.inputOf(event))).as(name)
                    .containsExactly(handledBy.get(event.getClass()));
        }
    }

    @Test
    void inputsCarryWhatTheBindingThreadNeeds() {
        DoorStateChanged changed = new DoorStateChanged();
        changed.doorId = "door1";
        changed.state = "closed";
        changed.previousState = "closing";
        assertThat(DoorBinding.INPUTS.inputOf(changed)).isEqualTo(new DoorInput.StateChanged("door1", "closed"));
        CommandOutcome outcome = new CommandOutcome();
        assertThat(DoorBinding.INPUTS.inputOf(outcome)).isEqualTo(new DoorInput.Outcome(outcome));
        assertThat(DoorBinding.INPUTS.inputOf(new BrainIoTEvent() {
        })).isNull();
    }

    /** @return the names of the handler's methods the input calls, in order */
    private static List<String> handledBy(DoorInput input) {
        List<String> calls = new ArrayList<>();
        input.handle((DoorInput.Handler) Proxy.newProxyInstance(DoorInput.Handler.class.getClassLoader(),
                new Class<?>[] { DoorInput.Handler.class }, (proxy, method, args) -> {
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
