package eu.brain.iot.scenario;

import java.util.List;
import java.util.regex.Pattern;

/** A fault the runner injects at a warehouse time (measured from the scenario's start). */
sealed interface PlannedFault permits PlannedFault.Offline, PlannedFault.StopBehaviour,
        PlannedFault.KillNode {

    long atMillis();

    /** When the fault ends by itself (a robot back online), or {@link #atMillis()} when it does not. */
    long endsAtMillis();

    /**
     * Whether a fault still going on when the run ends is ended then (a robot offline comes back, so that the end
     * state is judged fairly), rather than reported as not done (a node due to be started again).
     */
    default boolean endsWithTheRun() {
        return true;
    }

    /** @throws IllegalArgumentException when the fault names a robot the warehouse does not have */
    default void check(java.util.List<String> robotIds) {
    }

    /** Starts (or, with {@code start} false, ends) the fault through the injector; returns what was done. */
    String inject(FaultInjector injector, boolean start);

    /** What the fault does, for the progress output and the report. */
    String describe();

    /** One part of a fault's text read as a warehouse time; a mistake names the part. */
    private static long part(String prefix, String partName, String text) {
        try {
            return WarehouseTime.parseMillis(text);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException(prefix + "the " + partName + " " + e.getMessage(), e);
        }
    }

    /** The robot answers 503 and stands still from {@code atMillis} for {@code forMillis} (robot-sim's fault API). */
    record Offline(String robot, long atMillis, long forMillis) implements PlannedFault {
        private static final String HOW = "write ROBOT@TIME+DURATION, e.g. robot2@60s+30s (robot2 offline 60 s into "
                + "the scenario, for 30 s of warehouse time)";
        private static final Pattern ROBOT = Pattern.compile("[^@+\\s]+");

        /** {@code robot2@60s+30s}; a mistake is named by its part: ROBOT, TIME or DURATION. */
        static Offline parse(String spec) {
            String prefix = "--fault-offline '" + spec + "': ";
            int at = spec.indexOf('@');
            if (at < 0) {
                throw new IllegalArgumentException(prefix + HOW + "; the @TIME is missing");
            }
            String robot = spec.substring(0, at);
            if (!ROBOT.matcher(robot).matches()) {
                throw new IllegalArgumentException(prefix + HOW + "; "
                        + (robot.isEmpty() ? "the ROBOT before '@' is missing" : "'" + robot + "' is no ROBOT id"));
            }
            int plus = spec.indexOf('+', at);
            String time = plus < 0 ? spec.substring(at + 1) : spec.substring(at + 1, plus);
            long atMillis = PlannedFault.part(prefix, "TIME", time);
            if (plus < 0) {
                throw new IllegalArgumentException(prefix + HOW + "; the +DURATION is missing");
            }
            long forMillis = PlannedFault.part(prefix, "DURATION", spec.substring(plus + 1));
            if (forMillis <= 0) {
                throw new IllegalArgumentException(prefix + "the DURATION must be above 0");
            }
            return new Offline(robot, atMillis, forMillis);
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
        /** The project's behaviours by short name: each stands for {@value #PREFIX} and the name. */
        static final List<String> SHORT_NAMES = List.of("robot", "door", "orchestrator");
        private static final String PREFIX = "eu.brain.iot.behaviours.";
        private static final String HOW = "write BEHAVIOUR@TIME, e.g. robot@90s (BEHAVIOUR is "
                + String.join(", ", SHORT_NAMES) + ", or a bundle's full symbolic name, with a dot)";
        private static final Pattern SYMBOLIC_NAME = Pattern.compile("[A-Za-z0-9_\\-]+(\\.[A-Za-z0-9_\\-]+)+");

        /** {@code robot@90s}; a short name must be one of {@link #SHORT_NAMES}. */
        static StopBehaviour parse(String spec) {
            String prefix = "--stop-behaviour '" + spec + "': ";
            int at = spec.lastIndexOf('@');
            if (at < 0) {
                throw new IllegalArgumentException(prefix + HOW + "; the @TIME is missing");
            }
            String name = spec.substring(0, at);
            if (name.contains(".") ? !SYMBOLIC_NAME.matcher(name).matches() : !SHORT_NAMES.contains(name)) {
                throw new IllegalArgumentException(prefix + (name.isEmpty() ? "the BEHAVIOUR before '@' is missing"
                        : "no behaviour '" + name + "'") + "; " + HOW);
            }
            return new StopBehaviour(name, PlannedFault.part(prefix, "TIME", spec.substring(at + 1)));
        }

        /** The bundle's symbolic name: short names are the project's behaviours. */
        String symbolicName() {
            return behaviour.contains(".") ? behaviour : PREFIX + behaviour;
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

    /**
     * A fabric node's JVM killed outright at {@code atMillis} (SIGKILL, as {@code kill -9}: no goodbye to the fabric,
     * no lease given back); the other nodes are expected to take its devices when its lease lapses. With a downtime,
     * the node is started again that long after (its own configuration and state folder): it rejoins its fabric and
     * gets its share back from the nodes that held it.
     *
     * @param node       the node's name, {@code node1}..{@code nodeN}
     * @param downMillis how long after the kill it is started again; {@link #NOT_RESTARTED} for never
     */
    record KillNode(String node, long atMillis, long downMillis) implements PlannedFault {
        /** The downtime of a node that stays dead. */
        static final long NOT_RESTARTED = -1;
        private static final String HOW = "write NODE@TIME or NODE@TIME+DOWNTIME, e.g. node2@20s (node2 killed with "
                + "kill -9 20 s of warehouse time into the scenario) or node2@20s+30s (and started again 30 s later)";

        /**
         * {@code node2@20s} or {@code node2@20s+30s}; whether the node is one of the run's is checked by
         * {@link #checkNodes}.
         */
        static KillNode parse(String spec) {
            String prefix = "--kill-node '" + spec + "': ";
            int at = spec.indexOf('@');
            if (at < 0) {
                throw new IllegalArgumentException(prefix + HOW + "; the @TIME is missing");
            }
            String node = spec.substring(0, at);
            if (node.isEmpty()) {
                throw new IllegalArgumentException(prefix + HOW + "; the NODE before '@' is missing");
            }
            int plus = spec.indexOf('+', at);
            long atMillis = PlannedFault.part(prefix, "TIME", plus < 0 ? spec.substring(at + 1)
                    : spec.substring(at + 1, plus));
            if (plus < 0) {
                return new KillNode(node, atMillis, NOT_RESTARTED);
            }
            long down = PlannedFault.part(prefix, "DOWNTIME", spec.substring(plus + 1));
            if (down <= 0) {
                throw new IllegalArgumentException(prefix + "the DOWNTIME must be above 0");
            }
            return new KillNode(node, atMillis, down);
        }

        boolean restarted() {
            return downMillis > 0;
        }

        /**
         * @param nodes how many nodes the run has
         * @throws IllegalArgumentException when the node is not one of node1..nodeN, or the run has one node only
         */
        void checkNodes(int nodes) {
            if (nodes < 2) {
                throw new IllegalArgumentException("--kill-node " + node + ": the run has one node, and killing the "
                        + "only node would end the run: give --nodes 2 or more");
            }
            for (int k = 1; k <= nodes; k++) {
                if (Options.nodeName(k).equals(node)) {
                    return;
                }
            }
            throw new IllegalArgumentException("--kill-node: no node '" + node + "'; the run's nodes are "
                    + (nodes == 2 ? "node1, node2" : "node1.." + Options.nodeName(nodes)) + " (--nodes " + nodes + ")");
        }

        /** Whether the node is down at that warehouse time because of this kill. */
        private boolean downAt(long millis) {
            return millis >= atMillis && (!restarted() || millis < atMillis + downMillis);
        }

        /**
         * The kills of one run together: none finds its node down already, and at no time is every node down (the
         * run would end there).
         *
         * @throws IllegalArgumentException saying which kill and why
         */
        static void checkTogether(List<KillNode> kills, int nodes) {
            for (KillNode k : kills) {
                String at = WarehouseTime.format(k.atMillis);
                for (KillNode earlier : kills) {
                    if (earlier != k && earlier.node.equals(k.node) && earlier.downAt(k.atMillis)) {
                        String back = earlier.restarted()
                                ? ", started again at " + WarehouseTime.format(earlier.endsAtMillis()) : ", for good";
                        throw new IllegalArgumentException("--kill-node " + k.node + " at " + at + ": " + k.node
                                + " is down then (killed at " + WarehouseTime.format(earlier.atMillis) + back
                                + "): kill it once it is back, or give the earlier kill a shorter downtime");
                    }
                }
                long down = kills.stream().filter(o -> o.downAt(k.atMillis)).map(KillNode::node).distinct().count();
                if (down >= nodes) {
                    throw new IllegalArgumentException("--kill-node: at " + at + " every node of the run is down, "
                            + "which ends it: keep one running (or give a kill a downtime, +D, that brings its node "
                            + "back before)");
                }
            }
        }

        @Override
        public long endsAtMillis() {
            return restarted() ? atMillis + downMillis : atMillis;
        }

        @Override
        public boolean endsWithTheRun() {
            return false;
        }

        @Override
        public String inject(FaultInjector injector, boolean start) {
            return start ? injector.killNode(this) : injector.restartNode(this);
        }

        @Override
        public String describe() {
            return node + " killed (kill -9) at " + WarehouseTime.format(atMillis)
                    + (restarted() ? " and started again " + WarehouseTime.format(downMillis) + " later" : "");
        }
    }
}
