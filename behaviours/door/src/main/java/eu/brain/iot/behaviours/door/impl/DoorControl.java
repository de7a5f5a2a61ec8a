package eu.brain.iot.behaviours.door.impl;

import java.util.Comparator;
import java.util.List;
import java.util.Optional;

import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Reference;

import eu.brain.iot.behaviours.warehouse.CommandLedger;
import eu.brain.iot.behaviours.warehouse.FleetView;
import eu.brain.iot.behaviours.warehouse.FleetView.DoorState;
import eu.brain.iot.behaviours.warehouse.RobotNames;
import eu.brain.iot.behaviours.warehouse.RobotState;
import eu.brain.iot.edge.api.CloseDoorCommand;
import eu.brain.iot.edge.api.CommandOutcome;
import eu.brain.iot.edge.api.EdgeCommand;
import eu.brain.iot.edge.api.OpenDoorCommand;
import eu.brain.iot.edge.model.api.DeviceModel;
import eu.brain.iot.eventing.api.EventBus;

/**
 * The only place that sends doors commands (edge command events with a commandId, each outcome checked: a refusal
 * is logged with the door and the reason, counted, and an opening is asked again once). Which door opens: the door
 * in front of a robot of the asking group stopped at a closed door (the robot that broadcast {@code openDoor},
 * Listing 6), else the door nearest to one of the group's robots. Thread-safe: the view and the ledger are.
 */
@Component(service = DoorControl.class)
public final class DoorControl {

    private static final System.Logger LOG = System.getLogger(DoorControl.class.getName());

    private final FleetView view;
    private final CommandLedger ledger;

    @Activate
    public DoorControl(@Reference DeviceModel model, @Reference EventBus bus) {
        this.view = new FleetView(model);
        this.ledger = new CommandLedger(bus, "door-behaviour-");
    }

    FleetView view() {
        return view;
    }

    /** Opens the door a robot of the group waits at (else the door nearest to one of its robots). */
    void openForWaitingRobot(String group) {
        List<DoorState> doors = view.doors();
        List<RobotState> robots = view.robots().stream().filter(r -> RobotNames.inGroup(r.id(), group)).toList();
        Optional<DoorState> door = robots.stream().filter(RobotState::facesDoor)
                .flatMap(r -> doors.stream().filter(d -> d.cell().equals(r.ahead()))).findFirst();
        if (door.isEmpty()) {
            door = doors.stream().min(Comparator.comparingInt(d -> robots.stream()
                    .mapToInt(r -> r.cell().distance(d.cell())).min().orElse(Integer.MAX_VALUE)));
        }
        door.ifPresentOrElse(d -> send(new OpenDoorCommand(), d.id(), "a robot waits at it"),
                () -> LOG.log(System.Logger.Level.WARNING, "a robot asked for a door, but the edge knows none"));
    }

    void close(String door, String why) {
        send(new CloseDoorCommand(), door, why);
    }

    /** An outcome on the bus: a refused opening is asked again once; any refusal is logged. */
    void outcome(CommandOutcome o) {
        CommandLedger.Sent sent = ledger.answered(o);
        if (sent == null || o.accepted) {
            return;
        }
        LOG.log(System.Logger.Level.WARNING, "{0} refused {1} ({2}): {3} (status {4})", o.deviceId, o.command,
                sent.why(), o.reason, o.status);
        if (sent.command() instanceof OpenDoorCommand && !sent.why().endsWith(", again")) {
            send(new OpenDoorCommand(), sent.command().deviceId, sent.why() + ", again");
        }
    }

    long refused() {
        return ledger.refused();
    }

    private void send(EdgeCommand command, String door, String why) {
        command.deviceId = door;
        try {
            ledger.send(command, why);
        } catch (RuntimeException e) {
            LOG.log(System.Logger.Level.WARNING, "{0}: {1} not sent ({2}): {3}", door,
                    command.getClass().getSimpleName(), why, e.getMessage());
        }
    }
}
