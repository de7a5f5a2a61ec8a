package eu.brain.iot.edge.impl;

import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.function.Consumer;

import eu.brain.iot.edge.api.CancelMissionCommand;
import eu.brain.iot.edge.api.CloseDoorCommand;
import eu.brain.iot.edge.api.EdgeCommand;
import eu.brain.iot.edge.api.GoToCommand;
import eu.brain.iot.edge.api.OpenDoorCommand;
import eu.brain.iot.edge.api.PickCartCommand;
import eu.brain.iot.edge.api.PlaceCartCommand;

/**
 * The fleet's REST API as the edge uses it, in one place: where each thing is (the URL layout of robot-sim and
 * Robotnik's {@code robot_local_control}), the HTTP client with its connections and timeouts, and the reading of
 * the answers into typed results. Polling, mission tracking and commands all go through it.
 * <p>
 * Threads: {@link #configure} is called on the fleet thread; the other methods on any thread. The current
 * settings and client are one immutable {@link Link} in a volatile field, replaced as a whole; a request uses the
 * link it read. Answers are read on the client's threads (parsing included) and returned as futures.
 */
final class FleetApi implements AutoCloseable {

    /** The settings and the client made for them. */
    private record Link(FleetSettings settings, FleetHttpClient client) {
    }

    /** The device's answer to a command. */
    record CommandReply(boolean accepted, String reason, int status, Long missionId) {
    }

    private final AnswerParser parser = new AnswerParser();
    private final String nodeName;
    private volatile Link link;

    /** A fleet API of a node without a name ({@value EdgeNode#DEFAULT_NAME}). */
    FleetApi() {
        this(EdgeNode.DEFAULT_NAME);
    }

    /** @param nodeName the node's name, on every command the edge sends */
    FleetApi(String nodeName) {
        this.nodeName = nodeName;
    }

    /** New settings: a new client only when the connection settings changed. */
    void configure(FleetSettings next) {
        Link old = link;
        FleetHttpClient client = old != null && next.sameConnection(old.settings()) ? old.client()
                : new FleetHttpClient(next.ioThreads(), next.maxConnections(), next.timeoutMillis(), nodeName);
        link = new Link(next, client);
        if (old != null && old.client() != client) {
            old.client().close();
        }
    }

    /** @return the settings in force, {@code null} before the first configuration */
    FleetSettings settings() {
        Link l = link;
        return l == null ? null : l.settings();
    }

    /** Where a device answers polls. */
    URI stateUri(String id, DeviceKind kind) {
        return kind.stateUri(link.settings().baseUrl(), id);
    }

    /** The fleet's inventory ({@code GET /}); fails with a message saying what went wrong. */
    CompletableFuture<AnswerParser.Inventory> inventory() {
        return link.client().get(link.settings().baseUrl()).thenApply(answer -> {
            try {
                if (!answer.ok()) {
                    throw new DeviceIOException("HTTP " + answer.status() + ": " + parser.errorText(answer));
                }
                return parser.inventory(answer.body());
            } catch (DeviceIOException e) {
                throw new java.util.concurrent.CompletionException(e);
            }
        });
    }

    /** The fleet's world ({@code GET /world}: map and carts); fails with a message saying what went wrong. */
    CompletableFuture<WorldAnswer> world() {
        Link l = link;
        return l.client().get(l.settings().baseUrl().resolve("world")).thenApply(answer -> {
            try {
                if (!answer.ok()) {
                    throw new DeviceIOException("HTTP " + answer.status() + ": " + parser.errorText(answer));
                }
                return parser.world(answer.body());
            } catch (DeviceIOException e) {
                throw new java.util.concurrent.CompletionException(e);
            }
        });
    }

    /**
     * Poll one device; {@code done} gets the result on an HTTP thread, whatever happened (one callback, no future:
     * this is the hot path, 20,000 times a second for 10,000 robots).
     *
     * @param previousBody the bytes the device's current values came from, or {@code null}: the same bytes again
     *        give {@link PollResult.Unchanged} without parsing
     */
    void poll(String id, DeviceKind kind, URI stateUri, byte[] previousBody, Consumer<PollResult> done) {
        link.client().get(stateUri).whenComplete((answer, error) -> done.accept(read(id, kind, previousBody, answer,
                error)));
    }

    private PollResult read(String id, DeviceKind kind, byte[] previous, HttpAnswer answer, Throwable error) {
        Throwable cause = error instanceof java.util.concurrent.CompletionException c && c.getCause() != null
                ? c.getCause() : error;
        if (cause != null) {
            if (cause instanceof DeviceIOException e) {
                return e.notSent ? new PollResult.NotSent(e.getMessage()) : new PollResult.Failed(e.getMessage());
            }
            return new PollResult.Failed(String.valueOf(cause));
        }
        if (!answer.ok()) {
            return new PollResult.Failed("HTTP " + answer.status() + ": " + parser.errorText(answer));
        }
        if (previous != null && Arrays.equals(previous, answer.body())) {
            return new PollResult.Unchanged(answer.sentNanos());
        }
        try {
            DeviceAnswer parsed = kind == DeviceKind.ROBOT ? parser.robot(id, answer.body())
                    : parser.door(id, answer.body());
            return new PollResult.Answered(parsed, answer.body(), answer.sentNanos());
        } catch (DeviceIOException e) {
            return new PollResult.Failed(e.getMessage());
        } catch (RuntimeException e) {
            return new PollResult.Failed("unreadable answer: " + e);
        }
    }

    /**
     * How a mission that vanished from a robot's answers ended, from the robot's history ({@code query_state}).
     *
     * @return the ended mission, or empty when the history does not have it; fails when the history cannot be read
     */
    CompletableFuture<Optional<RobotAnswer.Mission>> endedMission(String robotId, RobotAnswer.Mission vanished) {
        String component = switch (vanished.type()) {
            case "pick" -> "PickComponent";
            case "place" -> "PlaceComponent";
            default -> "GoToComponent";
        };
        Link l = link;
        return l.client().get(component(l.settings().baseUrl(), robotId, component, "query_state"))
                .thenApply(answer -> {
                    try {
                        if (!answer.ok()) {
                            throw new DeviceIOException("HTTP " + answer.status());
                        }
                        RobotAnswer.Mission found = null;
                        for (RobotAnswer.Mission m : parser.history(robotId, answer.body())) {
                            if (m.id() == vanished.id() && m.ended()) {
                                found = m;
                            }
                        }
                        return Optional.ofNullable(found);
                    } catch (DeviceIOException e) {
                        throw new java.util.concurrent.CompletionException(e);
                    }
                });
    }

    /**
     * Send a command to its device (the caller has checked that the device exists and is of the right kind).
     *
     * @return the device's reply; a request that got no answer is a rejection with status 0
     * @throws IllegalArgumentException saying why the command cannot be sent
     */
    CompletableFuture<CommandReply> command(EdgeCommand command) {
        Link l = link;
        if (l == null) {
            throw new IllegalArgumentException("the edge is not configured yet");
        }
        URI base = l.settings().baseUrl();
        String device = command.deviceId;
        URI uri;
        String json;
        if (command instanceof GoToCommand g) {
            uri = component(base, device, "GoToComponent", "add");
            json = "{\"x\":" + g.x + ",\"y\":" + g.y + "}";
        } else if (command instanceof PickCartCommand) {
            uri = component(base, device, "PickComponent", "add");
            json = "{}";
        } else if (command instanceof PlaceCartCommand) {
            uri = component(base, device, "PlaceComponent", "add");
            json = "{}";
        } else if (command instanceof CancelMissionCommand c) {
            String type = c.missionType == null ? "goto" : c.missionType;
            String component = switch (type) {
                case "goto" -> "GoToComponent";
                case "pick" -> "PickComponent";
                case "place" -> "PlaceComponent";
                default -> throw new IllegalArgumentException("missionType must be goto, pick or place, found '"
                        + type + "'");
            };
            uri = component(base, device, component, "cancel");
            json = c.missionId == null ? "{}" : "{\"id\":" + c.missionId + "}";
        } else if (command instanceof OpenDoorCommand || command instanceof CloseDoorCommand) {
            uri = base.resolve(device + "/door_controller/command");
            json = command instanceof OpenDoorCommand ? "{\"data\":1.0}" : "{\"data\":0.0}";
        } else {
            throw new IllegalArgumentException("unsupported command " + command.getClass().getName()
                    + " (supported: GoToCommand, PickCartCommand, PlaceCartCommand, CancelMissionCommand, "
                    + "OpenDoorCommand, CloseDoorCommand)");
        }
        return l.client().post(uri, json.getBytes(StandardCharsets.UTF_8)).handle((answer, error) -> {
            if (error != null) {
                Throwable cause = error instanceof java.util.concurrent.CompletionException c && c.getCause() != null
                        ? c.getCause() : error;
                return new CommandReply(false, cause.getMessage(), 0, null);
            }
            if (!answer.ok()) {
                return new CommandReply(false, parser.errorText(answer), answer.status(), null);
            }
            return new CommandReply(true, null, answer.status(), parser.missionId(answer.body()));
        });
    }

    /** The URI of a robot's mission component. */
    private static URI component(URI base, String robotId, String component, String verb) {
        return base.resolve(robotId + "/robot_local_control/NavigationComponent/" + component + "/" + verb);
    }

    @Override
    public void close() {
        Link l = link;
        if (l != null) {
            l.client().close();
        }
    }
}
