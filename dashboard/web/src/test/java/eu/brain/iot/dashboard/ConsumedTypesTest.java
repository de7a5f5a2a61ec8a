package eu.brain.iot.dashboard;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Test;

import eu.brain.iot.federation.api.FabricProperties;

/**
 * The dashboard's consumer registers exactly {@link ConsumedTypes#CONSUMED}, which holds none of the behaviours'
 * triggers (the BMS would otherwise never install them). The browser tests check the same against the behaviour
 * repository's index, with a node that installs a behaviour on demand.
 */
class ConsumedTypesTest {

    @Test
    void theBusListenerRegistersTheListedTypesAndNoTrigger() throws Exception {
        String xml = Files.readString(Path.of("target/classes/OSGI-INF/eu.brain.iot.dashboard.BusListener.xml"));
        Matcher m = Pattern.compile("name=\"eu.brain.iot.behaviour.consumed\" type=\"String\">([^<]*)<").matcher(xml);
        assertThat(m.find()).as("the consumed property in " + xml).isTrue();
        List<String> registered = List.of(m.group(1).strip().split("\\s+"));

        assertThat(registered).containsExactlyInAnyOrderElementsOf(ConsumedTypes.CONSUMED);
        assertThat(registered).doesNotContainAnyElementsOf(ConsumedTypes.NEVER)
                .noneMatch(t -> t.startsWith(ConsumedTypes.BEHAVIOUR_EVENTS) && !t.endsWith(".TransitionFired"));
    }

    /**
     * The fabric does not announce the dashboard's consumer to other nodes (the federation's
     * {@code LocalConsumersIntegrationTest} checks that it leaves such a consumer out): its interest would pull every
     * node's commands and outcomes to each node that runs a dashboard.
     */
    @Test
    void theBusListenerStaysLocalToItsNode() throws Exception {
        String xml = Files.readString(Path.of("target/classes/OSGI-INF/eu.brain.iot.dashboard.BusListener.xml"));
        assertThat(xml).as("the local-only property in " + xml)
                .contains("name=\"" + FabricProperties.LOCAL_ONLY + "\" type=\"Boolean\" value=\"true\"");
    }
}
