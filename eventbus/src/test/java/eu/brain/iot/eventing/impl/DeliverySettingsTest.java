package eu.brain.iot.eventing.impl;

import static org.assertj.core.api.Assertions.assertThat;

import java.lang.reflect.Proxy;
import java.util.Map;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;

/** How the bus's configuration becomes the delivery pool's settings. */
class DeliverySettingsTest {

    /** A configuration as Declarative Services would build it: the given values, defaults for the rest. */
    private static BusConfig config(Map<String, Object> values) {
        return (BusConfig) Proxy.newProxyInstance(BusConfig.class.getClassLoader(), new Class<?>[] {BusConfig.class},
                (proxy, method, args) -> values.getOrDefault(method.getName(), method.getDefaultValue()));
    }

    @Test
    void byDefaultOneWorkerPerCoreButNeverFewerThanTwo() {
        DeliveryPool.Settings settings = EventBusComponent.deliverySettings(config(Map.of()), 4);
        assertThat(settings.workers()).isEqualTo(4);

        // on one core still two workers: one behaviour blocked in notify() cannot hold up the others
        settings = EventBusComponent.deliverySettings(config(Map.of()), 1);
        assertThat(settings.workers()).isEqualTo(2);
        assertThat(settings.stallThresholdNanos()).isEqualTo(TimeUnit.MILLISECONDS.toNanos(5));
        assertThat(settings.idleSpinNanos()).isEqualTo(TimeUnit.MICROSECONDS.toNanos(50));
    }

    @Test
    void aConfiguredWorkerCountIsTakenAsItIsAndTheStallThresholdIsAtLeastOneMillisecond() {
        DeliveryPool.Settings settings = EventBusComponent.deliverySettings(
                config(Map.of("delivery_workers", 1, "stall_threshold_ms", 0L)), 4);

        assertThat(settings.workers()).isEqualTo(1);
        assertThat(settings.stallThresholdNanos()).isEqualTo(TimeUnit.MILLISECONDS.toNanos(1));
    }
}
