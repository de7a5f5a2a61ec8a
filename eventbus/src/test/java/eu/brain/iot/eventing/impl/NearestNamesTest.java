package eu.brain.iot.eventing.impl;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;

import org.junit.jupiter.api.Test;

class NearestNamesTest {

    static final List<String> KNOWN = List.of("eu.brain.iot.edge.api.GoToCommand", "eu.brain.iot.edge.api.OpenDoorCommand",
            "eu.brain.iot.behaviours.events.ConnectorTypeDoor", "eu.brain.iot.behaviours.events.ConnectorTypeRobot");

    @Test
    void caseThenSimpleNameThenFewEdits() {
        assertThat(NearestNames.nearest("eu.brain.iot.edge.api.gotocommand", KNOWN))
                .first().isEqualTo("eu.brain.iot.edge.api.GoToCommand");
        assertThat(NearestNames.nearest("ConnectorTypeDoor", KNOWN))
                .first().isEqualTo("eu.brain.iot.behaviours.events.ConnectorTypeDoor");
        assertThat(NearestNames.nearest("eu.brain.iot.edge.api.OpenDorCommand", KNOWN))
                .containsExactly("eu.brain.iot.edge.api.OpenDoorCommand");
        assertThat(NearestNames.nearest("org.example.Greeting", KNOWN)).isEmpty();
    }

    @Test
    void distanceStopsEarlyBeyondTheLimit() {
        assertThat(NearestNames.distance("kitten", "sitting", 5)).isEqualTo(3);
        assertThat(NearestNames.distance("abcdefgh", "zzzzzzzz", 2)).isEqualTo(3);
    }
}
