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
        Map<String, Object> none = Map.of();
        assertThat(EdgeComponent.fleetUrl(config(none), none, "http://127.0.0.1:18090/"))
                .isEqualTo("http://127.0.0.1:18090/");
        assertThat(EdgeComponent.fleetUrl(config(none), none, null)).isEqualTo("http://127.0.0.1:8090/");
    }

    @Test
    void theConfigurationWins() {
        Map<String, Object> set = Map.of("fleet.url", "http://fleet.example:8080/");
        assertThat(EdgeComponent.fleetUrl(config(set), set, "http://127.0.0.1:18090/"))
                .isEqualTo("http://fleet.example:8080/");
    }
}
