package eu.brain.iot.scenario;

import java.util.regex.Matcher;
import java.util.regex.Pattern;

/** A fault the runner injects at a warehouse time (measured from the scenario's start). */
sealed interface PlannedFault permits PlannedFault.Offline, PlannedFault.StopBehaviour {

    long atMillis();

    /** When the fault ends by itself (a robot back online), or {@link #atMillis()} when it does not. */
    long endsAtMillis();

    /** @throws IllegalArgumentException when the fault names a robot the warehouse does not have */
    default void check(java.util.List<String> robotIds) {
    }

    /** Starts (or, with {@code start} false, ends) the fault through the injector; returns what was done. */
    String inject(FaultInjector injector, boolean start);

    /** What the fault does, for the progress output and the report. */
    String describe();

    /** The robot answers 503 and stands still from {@code atMillis} for {@code forMillis} (robot-sim's fault API). */
    record Offline(String robot, long atMillis, long forMillis) implements PlannedFault {
        private static final Pattern SPEC = Pattern.compile("([^@+\\s]+)@([^+]+)\\+(.+)");

        /** {@code robot2@60s+30s}. */
        static Offline parse(String spec) {
            Matcher m = SPEC.matcher(spec);
            if (!m.matches()) {
                throw new IllegalArgumentException("--fault-offline '" + spec + "': write ROBOT@TIME+DURATION, "
                        + "e.g. robot2@60s+30s (robot2 offline 60 s into the scenario, for 30 s of warehouse time)");
            }
            long forMillis = WarehouseTime.parseMillis(m.group(3));
            if (forMillis <= 0) {
                throw new IllegalArgumentException("--fault-offline '" + spec + "': the duration must be above 0");
            }
            return new Offline(m.group(1), WarehouseTime.parseMillis(m.group(2)), forMillis);
        }

        @Override
        public long endsAtMillis() {
            return atMillis + forMillis;
        }

        @Override
        public void check(java.util.List<String> robotIds) {
            if (!robotIds.contains(robot)) {
                throw new IllegalArgumentException("--fault-offline: no robot '" + robot + "' in this warehouse ("
                        + String.join(", ", robotIds.size() > 5 ? robotIds.subList(0, 5) : robotIds)
                        + (robotIds.size() > 5 ? ", ... robot" + robotIds.size() : "") + ")");
            }
        }

        @Override
        public String inject(FaultInjector injector, boolean start) {
            return injector.offline(this, start);
        }

        @Override
        public String describe() {
            return robot + " offline at " + WarehouseTime.format(atMillis) + " for " + WarehouseTime.format(forMillis);
        }
    }

    /**
     * The behaviour bundle is stopped in the node at {@code atMillis} (through the node's Gogo shell, as an operator
     * would type {@code stop <id>}); the BMS is expected to bring it back.
     *
     * @param behaviour {@code robot}, {@code door}, {@code orchestrator} or a bundle symbolic name
     */
    record StopBehaviour(String behaviour, long atMillis) implements PlannedFault {
        private static final Pattern SPEC = Pattern.compile("([A-Za-z0-9_.\\-]+)@(.+)");

        /** {@code robot@90s}. */
        static StopBehaviour parse(String spec) {
            Matcher m = SPEC.matcher(spec);
            if (!m.matches()) {
                throw new IllegalArgumentException("--stop-behaviour '" + spec + "': write BEHAVIOUR@TIME, e.g. "
                        + "robot@90s (robot, door, orchestrator or a bundle symbolic name)");
            }
            return new StopBehaviour(m.group(1), WarehouseTime.parseMillis(m.group(2)));
        }

        /** The bundle's symbolic name: short names are the project's behaviours. */
        String symbolicName() {
            return behaviour.contains(".") ? behaviour : "eu.brain.iot.behaviours." + behaviour;
        }

        @Override
        public long endsAtMillis() {
            return atMillis;
        }

        @Override
        public String inject(FaultInjector injector, boolean start) {
            return injector.stopBehaviour(this);
        }

        @Override
        public String describe() {
            return "behaviour bundle " + symbolicName() + " stopped at " + WarehouseTime.format(atMillis);
        }
    }
}
