package eu.brain.iot.bip.smc;

import java.util.List;

import eu.brain.iot.bip.smc.runtime.SimulationExterns;
import eu.brain.iot.bip.smc.runtime.TraceRandom;

/** The simulation of Sensor.bip's {@code read(id)}: 1 with probability 0.25, else 0. */
public final class SensorSimulation implements SimulationExterns {
    @Override
    public Object call(String name, List<String> paramTypes, String resultType, Object[] args, TraceRandom random) {
        if (name.equals("read") && (Integer) args[0] == 7) {
            return random.bernoulli(0.25) ? 1 : 0;
        }
        throw new IllegalArgumentException("no simulation of " + name);
    }
}
