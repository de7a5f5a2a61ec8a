package eu.brain.iot.dashboard;

import java.util.List;

/**
 * The event types the dashboard takes from the bus, by name (so that it depends on no behaviour bundle), and the
 * ones it must never take.
 * <p>
 * The BMS installs a behaviour only for an event that no installed consumer takes. A consumer of a behaviour's
 * trigger would therefore stop that behaviour from ever being installed on demand: robot and door changes come
 * from the device model's listener instead of {@code RobotPositionChanged} and {@code DoorStateChanged}, and none
 * of the behaviours' own connector events is consumed (their counts come from the bus's statistics, which consume
 * nothing). What is consumed here is what the edge publishes about commands and what robots saw, the commands
 * themselves (the edge consumes them anyway), the BMS's alerts, and the behaviours' trace events.
 */
final class ConsumedTypes {

    static final String EDGE = "eu.brain.iot.edge.api.";

    static final List<String> CONSUMED = List.of(
            EDGE + "CommandOutcome",
            EDGE + "GoToCommand", EDGE + "PickCartCommand", EDGE + "PlaceCartCommand",
            EDGE + "OpenDoorCommand", EDGE + "CloseDoorCommand", EDGE + "CancelMissionCommand",
            EDGE + "ObstacleDetected", EDGE + "ObstacleCleared",
            EDGE + "CartLifted", EDGE + "CartPlaced",
            EDGE + "MissionFinished", EDGE + "MissionFailed",
            EDGE + "DeviceUnreachable", EDGE + "DeviceRecovered",
            "eu.brain.iot.bms.api.BehaviourInstalled", "eu.brain.iot.bms.api.BehaviourInstallFailed",
            "eu.brain.iot.bms.api.BehaviourNotFound",
            "eu.brain.iot.behaviours.events.TransitionFired");

    /** Triggers of the behaviours installed on demand, and their supertypes: never consumed. */
    static final List<String> NEVER = List.of(
            EDGE + "RobotPositionChanged", EDGE + "DoorStateChanged", EDGE + "RobotEvent",
            "eu.brain.iot.eventing.api.BrainIoTEvent");

    /** The behaviours' connector events, counted from the bus's statistics (never consumed: they are triggers). */
    static final String BEHAVIOUR_EVENTS = "eu.brain.iot.behaviours.events.";

    private ConsumedTypes() {
    }
}
