package eu.brain.iot.benchmarks.driver.ours;

import eu.brain.iot.benchmarks.spi.ConsumerProbe;
import eu.brain.iot.eventing.api.SmartBehaviour;

/** A smart behaviour that reports every event to its probe. */
final class ProbeBehaviour implements SmartBehaviour<PositionEvent> {

    private final ConsumerProbe probe;

    ProbeBehaviour(ConsumerProbe probe) {
        this.probe = probe;
    }

    @Override
    public void notify(PositionEvent event) {
        probe.onEvent(event.sentNanos);
    }
}
