package eu.brain.iot.edge.impl;

import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.util.UUID;
import java.util.concurrent.CompletableFuture;

import eu.brain.iot.edge.api.CancelMissionCommand;
import eu.brain.iot.edge.api.CloseDoorCommand;
import eu.brain.iot.edge.api.CommandOutcome;
import eu.brain.iot.edge.api.EdgeCommand;
import eu.brain.iot.edge.api.GoToCommand;
import eu.brain.iot.edge.api.OpenDoorCommand;
import eu.brain.iot.edge.api.PickCartCommand;
import eu.brain.iot.edge.api.PlaceCartCommand;
import eu.brain.iot.eventing.api.BrainIoTEvent;

/**
 * Performs a command over the device's REST API and publishes its {@link CommandOutcome}: accepted when the
 * device said yes, else rejected with what the device (or the edge, for a command it cannot send) said.
 * Thread-safe: it keeps no state of its own.
 */
final class CommandRunner {

    private final FleetPoller fleet;
    private final DeviceStore store;
    /** Hands an outcome to the fleet thread, which publishes it in line with the edge's other events. */
    private final java.util.function.Consumer<BrainIoTEvent> events;
    private final AnswerParser parser = new AnswerParser();

    CommandRunner(FleetPoller fleet, DeviceStore store, java.util.function.Consumer<BrainIoTEvent> events) {
        this.fleet = fleet;
        this.store = store;
        this.events = events;
    }

    private record Call(URI uri, String json) {
    }

    CompletableFuture<CommandOutcome> run(EdgeCommand command) {
        CommandOutcome outcome = new CommandOutcome();
        outcome.commandId = command.commandId != null ? command.commandId : UUID.randomUUID().toString();
        outcome.deviceId = command.deviceId;
        outcome.command = command.getClass().getSimpleName();
        Call call;
        FleetHttpClient client = fleet.client();
        try {
            if (client == null) {
                throw new IllegalArgumentException("the edge is not configured yet");
            }
            call = call(command, fleet.settings().baseUrl());
        } catch (IllegalArgumentException e) {
            return CompletableFuture.completedFuture(finish(outcome, false, e.getMessage(), 0));
        }
        return client.post(call.uri(), call.json().getBytes(StandardCharsets.UTF_8)).handle((answer, error) -> {
            if (error != null) {
                return finish(outcome, false, error.getMessage(), 0);
            }
            if (!answer.ok()) {
                return finish(outcome, false, parser.errorText(answer), answer.status());
            }
            outcome.missionId = parser.missionId(answer.body());
            return finish(outcome, true, null, answer.status());
        });
    }

    private CommandOutcome finish(CommandOutcome outcome, boolean accepted, String reason, int status) {
        outcome.accepted = accepted;
        outcome.reason = reason;
        outcome.status = status;
        events.accept(outcome);
        return outcome;
    }

    /** @throws IllegalArgumentException saying why the command cannot be sent */
    private Call call(EdgeCommand command, URI base) {
        String device = command.deviceId;
        if (device == null || device.isBlank()) {
            throw new IllegalArgumentException(command.getClass().getSimpleName() + " has no deviceId");
        }
        String kind = store.kind(device);
        if (kind == null) {
            throw new IllegalArgumentException("unknown device '" + device + "' (robots: "
                    + store.ids(DeviceKind.ROBOT.label) + ", doors: " + store.ids(DeviceKind.DOOR.label) + ")");
        }
        boolean forDoor = command instanceof OpenDoorCommand || command instanceof CloseDoorCommand;
        String wanted = forDoor ? DeviceKind.DOOR.label : DeviceKind.ROBOT.label;
        if (!kind.equals(wanted)) {
            throw new IllegalArgumentException(command.getClass().getSimpleName() + " is for a " + wanted + "; "
                    + device + " is a " + kind);
        }
        if (command instanceof GoToCommand g) {
            return new Call(FleetPoller.component(base, device, "GoToComponent", "add"),
                    "{\"x\":" + g.x + ",\"y\":" + g.y + "}");
        }
        if (command instanceof PickCartCommand) {
            return new Call(FleetPoller.component(base, device, "PickComponent", "add"), "{}");
        }
        if (command instanceof PlaceCartCommand) {
            return new Call(FleetPoller.component(base, device, "PlaceComponent", "add"), "{}");
        }
        if (command instanceof CancelMissionCommand c) {
            String type = c.missionType == null ? "goto" : c.missionType;
            String component = switch (type) {
                case "goto" -> "GoToComponent";
                case "pick" -> "PickComponent";
                case "place" -> "PlaceComponent";
                default -> throw new IllegalArgumentException("missionType must be goto, pick or place, found '"
                        + type + "'");
            };
            return new Call(FleetPoller.component(base, device, component, "cancel"),
                    c.missionId == null ? "{}" : "{\"id\":" + c.missionId + "}");
        }
        if (forDoor) {
            return new Call(base.resolve(device + "/door_controller/command"),
                    command instanceof OpenDoorCommand ? "{\"data\":1.0}" : "{\"data\":0.0}");
        }
        throw new IllegalArgumentException("unsupported command " + command.getClass().getName()
                + " (supported: GoToCommand, PickCartCommand, PlaceCartCommand, CancelMissionCommand, "
                + "OpenDoorCommand, CloseDoorCommand)");
    }
}
