package eu.brain.iot.behaviours.robot.impl;

import eu.brain.iot.edge.api.CommandOutcome;

/**
 * What {@link RobotBinding} hands from the bus to its own thread: one kind per event it consumes, carrying just
 * what the binding thread needs. Threads: made on the bus's delivery thread by {@link RobotBinding#notify} (from the
 * event, by the table {@code RobotBinding.INPUTS}), immutable, handled on the binding thread with a {@link Handler}.
 */
sealed interface RobotInput {

    /** Calls the handler's method for this kind of input. */
    void handle(Handler handler);

    /** The binding thread's treatment of each kind of input. */
    interface Handler {
        void outcome(Outcome outcome);

        void missionEnded(MissionEnded ended);

        void moved(Moved moved);

        void obstacle(Obstacle obstacle);

        void unreachable(Unreachable unreachable);

        void recovered(Recovered recovered);

        void reported(Reported reported);
    }

    /**
     * The edge's answer to a command ({@code CommandOutcome}), for {@link RobotFleet#outcome}, which takes the event
     * itself: an event is not changed once published.
     */
    record Outcome(CommandOutcome outcome) implements RobotInput {
        @Override
        public void handle(Handler handler) {
            handler.outcome(this);
        }
    }

    /**
     * A robot's mission ended: {@code MissionFinished} ({@code failed} false, no reason) or {@code MissionFailed}
     * ({@code failed} true, with the edge's reason: {@code "cancelled"} for a cancelled mission; it may be null).
     */
    record MissionEnded(String robot, String type, Integer goalX, Integer goalY, boolean failed, String reason)
            implements RobotInput {
        @Override
        public void handle(Handler handler) {
            handler.missionEnded(this);
        }
    }

    /**
     * The robot's position or state changed ({@code RobotPositionChanged}); {@code appeared}: without a previous cell,
     * the robot was discovered, or taken over by the node that polls it now.
     */
    record Moved(String robot, boolean appeared) implements RobotInput {
        @Override
        public void handle(Handler handler) {
            handler.moved(this);
        }
    }

    /** The robot stopped at an obstacle ({@code ObstacleDetected}), or its way is clear ({@code ObstacleCleared}). */
    record Obstacle(String robot, boolean cleared) implements RobotInput {
        @Override
        public void handle(Handler handler) {
            handler.obstacle(this);
        }
    }

    /** The edge cannot reach a device, of any kind ({@code DeviceUnreachable}). */
    record Unreachable(String device, String reason) implements RobotInput {
        @Override
        public void handle(Handler handler) {
            handler.unreachable(this);
        }
    }

    /** A device, of any kind ({@code "robot"}, {@code "door"}), answers again ({@code DeviceRecovered}). */
    record Recovered(String device, String kind, long downMillis) implements RobotInput {
        @Override
        public void handle(Handler handler) {
            handler.recovered(this);
        }
    }

    /** A robot's model instance as its host reports it ({@code RobotModelReport}), taken as it is. */
    record Reported(RobotModelReport report) implements RobotInput {
        @Override
        public void handle(Handler handler) {
            handler.reported(this);
        }
    }
}
