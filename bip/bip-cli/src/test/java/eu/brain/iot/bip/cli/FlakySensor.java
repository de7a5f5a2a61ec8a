package eu.brain.iot.bip.cli;

import java.util.List;

import eu.brain.iot.bip.smc.runtime.SimulationExterns;
import eu.brain.iot.bip.smc.runtime.TraceRandom;

/** Sensor.bip's read(7), unplugged now and then: throws on about 1 call in 200 (drawn from the trace's random). */
public final class FlakySensor implements SimulationExterns {

    @Override
    public Object call(String name, List<String> types, String result, Object[] args, TraceRandom random) {
        if (random.uniform(0, 199) == 0) {
            throw new IllegalStateException("sensor " + args[0] + " unplugged");
        }
        return random.bernoulli(0.25) ? 1 : 0;
    }
}
