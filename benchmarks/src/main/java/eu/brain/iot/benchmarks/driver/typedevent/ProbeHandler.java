package eu.brain.iot.benchmarks.driver.typedevent;

import org.osgi.service.typedevent.TypedEventHandler;

import eu.brain.iot.benchmarks.spi.ConsumerProbe;

/** A typed event handler that reports every event to its probe. */
final class ProbeHandler implements TypedEventHandler<Position> {

    private final ConsumerProbe probe;

    ProbeHandler(ConsumerProbe probe) {
        this.probe = probe;
    }

    @Override
    public void notify(String topic, Position event) {
        probe.onEvent(event.sentNanos);
    }
}
