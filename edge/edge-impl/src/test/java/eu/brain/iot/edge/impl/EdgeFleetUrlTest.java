package eu.brain.iot.edge.impl;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Map;

import org.junit.jupiter.api.Test;
import org.osgi.util.converter.Converters;

/** Which fleet the edge polls: its configuration, else the framework property ./fabric-node --fleet-port=N sets. */
class EdgeFleetUrlTest {

    private static EdgeConfig config(Map<String, Object> properties) {
        return Converters.standardConverter().convert(properties).to(EdgeConfig.class);
    }

    @Test
    void theFrameworkPropertyWhenTheConfigurationSetsNone() {
        // what DS gives without a configuration: bnd put the type's defaults in the component's properties
        EdgeConfig none = config(Map.of("fleet.url", EdgeConfig.DEFAULT_FLEET_URL));
        assertThat(EdgeComponent.fleetUrl(none, "http://127.0.0.1:18090/")).isEqualTo("http://127.0.0.1:18090/");
        assertThat(EdgeComponent.fleetUrl(config(Map.of()), "http://127.0.0.1:18090/"))
                .isEqualTo("http://127.0.0.1:18090/");
        assertThat(EdgeComponent.fleetUrl(none, null)).isEqualTo("http://127.0.0.1:8090/");
    }

    @Test
    void theConfigurationWins() {
        EdgeConfig set = config(Map.of("fleet.url", "http://fleet.example:8080/"));
        assertThat(EdgeComponent.fleetUrl(set, "http://127.0.0.1:18090/")).isEqualTo("http://fleet.example:8080/");
    }
}
