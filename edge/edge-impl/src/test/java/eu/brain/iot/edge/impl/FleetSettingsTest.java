package eu.brain.iot.edge.impl;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.List;

import org.junit.jupiter.api.Test;

/** A bad configuration is refused with the property's name and what to write instead. */
class FleetSettingsTest {

    private static FleetSettings of(String url, List<String> robots, long period, long backoffMax) {
        return FleetSettings.of(url, robots, List.of(), period, 1000, 8, 1, 3, backoffMax);
    }

    @Test
    void acceptsAndNormalisesTheBaseUrl() {
        assertThat(of("http://127.0.0.1:8090", List.of(), 500, 8000).baseUrl().toString())
                .isEqualTo("http://127.0.0.1:8090/");
        assertThat(of("http://fleet.local:80/api/", List.of("robot1"), 500, 8000).discover()).isFalse();
    }

    @Test
    void namesWhatIsWrong() {
        assertThatThrownBy(() -> of("ftp://x/", List.of(), 500, 8000)).hasMessage(
                "fleet.url must be an http URL such as http://127.0.0.1:8090/, found 'ftp://x/'");
        assertThatThrownBy(() -> of("http://h/", List.of("robot 1"), 500, 8000)).hasMessage(
                "robots holds 'robot 1': a device id is letters, digits, '_', '.' or '-'");
        assertThatThrownBy(() -> of("http://h/", List.of(), 0, 8000)).hasMessage("poll.period.ms must be positive, found 0");
        assertThatThrownBy(() -> of("http://h/", List.of(), 500, 100)).hasMessage(
                "backoff.max.ms (100) must be at least poll.period.ms (500)");
    }
}
