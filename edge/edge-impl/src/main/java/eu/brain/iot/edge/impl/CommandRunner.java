package eu.brain.iot.edge.impl;

import java.util.UUID;
import java.util.concurrent.CompletableFuture;
import java.util.function.Consumer;

import eu.brain.iot.edge.api.CloseDoorCommand;
import eu.brain.iot.edge.api.CommandOutcome;
import eu.brain.iot.edge.api.EdgeCommand;
import eu.brain.iot.edge.api.OpenDoorCommand;
import eu.brain.iot.eventing.api.BrainIoTEvent;

/**
 * Performs a command through the {@link FleetApi} and publishes its {@link CommandOutcome}: accepted when the
 * device said yes, else rejected with what the device (or the edge, for a command it cannot send) said.
 * Thread-safe: it keeps no state of its own; outcomes are handed to the fleet thread, which publishes them in
 * line with the edge's other events ({@link Outbox}).
 */
final class CommandRunner {

    private final FleetApi api;
    private final DeviceStore store;
    private final Consumer<BrainIoTEvent> events;

    CommandRunner(FleetApi api, DeviceStore store, Consumer<BrainIoTEvent> events) {
        this.api = api;
        this.store = store;
        this.events = events;
    }

    CompletableFuture<CommandOutcome> run(EdgeCommand command) {
        CommandOutcome outcome = outcome(command);
        CompletableFuture<FleetApi.CommandReply> reply;
        try {
            check(command);
            reply = api.command(command);
        } catch (IllegalArgumentException e) {
            return CompletableFuture.completedFuture(finish(outcome, false, e.getMessage(), 0, null));
        }
        return reply.thenApply(r -> finish(outcome, r.accepted(), r.reason(), r.status(), r.missionId()));
    }

    /** Refuses the command without sending it, publishing why. */
    CompletableFuture<CommandOutcome> refuse(EdgeCommand command, String reason) {
        return CompletableFuture.completedFuture(finish(outcome(command), false, reason, 0, null));
    }

    private static CommandOutcome outcome(EdgeCommand command) {
        CommandOutcome outcome = new CommandOutcome();
        outcome.commandId = command.commandId != null ? command.commandId : UUID.randomUUID().toString();
        outcome.deviceId = command.deviceId;
        outcome.command = command.getClass().getSimpleName();
        return outcome;
    }

    private CommandOutcome finish(CommandOutcome outcome, boolean accepted, String reason, int status,
            Long missionId) {
        outcome.accepted = accepted;
        outcome.reason = reason;
        outcome.status = status;
        outcome.missionId = missionId;
        events.accept(outcome);
        return outcome;
    }

    /** @throws IllegalArgumentException saying why the command cannot be sent to its device */
    private void check(EdgeCommand command) {
        String device = command.deviceId;
        if (device == null || device.isBlank()) {
            throw new IllegalArgumentException(command.getClass().getSimpleName() + " has no deviceId");
        }
        DeviceKind kind = store.kind(device);
        if (kind == null) {
            throw new IllegalArgumentException("unknown device '" + device + "' (robots: "
                    + store.ids(DeviceKind.ROBOT) + ", doors: " + store.ids(DeviceKind.DOOR) + ")");
        }
        boolean forDoor = command instanceof OpenDoorCommand || command instanceof CloseDoorCommand;
        DeviceKind wanted = forDoor ? DeviceKind.DOOR : DeviceKind.ROBOT;
        if (kind != wanted) {
            throw new IllegalArgumentException(command.getClass().getSimpleName() + " is for a " + wanted.label
                    + "; " + device + " is a " + kind.label);
        }
    }
}
