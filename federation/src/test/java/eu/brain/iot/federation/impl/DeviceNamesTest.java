package eu.brain.iot.federation.impl;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.HashMap;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;

/** Which devices an event names: the text of its robotId, doorId and deviceId fields, sorted, none twice. */
class DeviceNamesTest {

    @Test
    void theDeviceFieldsOfAnEventNameItsDevices() {
        assertThat(DeviceNames.of(Map.of("robotId", "robot2", "seq", 4L))).containsExactly("robot2");
        assertThat(DeviceNames.of(Map.of("doorId", "door1", "robotId", "robot2", "deviceId", "robot2")))
                .containsExactly("door1", "robot2");
    }

    @Test
    void otherFieldsBlankOrNonTextValuesAndNoEventNameNone() {
        Map<String, Object> event = new HashMap<>();
        event.put("cartId", "cart1");
        event.put("commandId", "c-1");
        event.put("robotId", " ");
        event.put("doorId", 7);
        event.put("deviceId", null);
        assertThat(DeviceNames.of(event)).isEmpty();
        assertThat(DeviceNames.of(null)).isEmpty();
        assertThat(DeviceNames.of(Map.of("nested", Map.of("robotId", "robot1")))).isEqualTo(List.of());
    }
}
