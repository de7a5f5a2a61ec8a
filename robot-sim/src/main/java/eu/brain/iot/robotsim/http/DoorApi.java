package eu.brain.iot.robotsim.http;

import eu.brain.iot.robotsim.WorldThread;
import eu.brain.iot.robotsim.view.DoorView;
import eu.brain.iot.robotsim.view.ViewPublisher;
import io.netty.handler.codec.http.HttpMethod;
import java.util.List;
import java.util.Set;

/** {@code /{door}/door_controller/command} ({@code {"data":1.0}} opens, {@code 0.0} closes) and {@code .../state}. */
final class DoorApi {
    private static final Set<String> COMMAND_FIELDS = Set.of("data");

    private final WorldThread world;
    private final ViewPublisher views;
    private final CommandCounter commands;

    DoorApi(WorldThread world, ViewPublisher views, CommandCounter commands) {
        this.world = world;
        this.views = views;
        this.commands = commands;
    }

    /** @param rest the path segments after {@code door_controller} */
    void handle(ServerExchange ex, int door, List<String> rest) {
        if (rest.size() != 1) {
            Route.notFound(ex);
            return;
        }
        switch (rest.get(0)) {
            case "state" -> {
                if (Route.methodIs(ex, HttpMethod.GET)) {
                    ex.json(200, views.door(door));
                }
            }
            case "command" -> {
                if (ex.method().equals(HttpMethod.POST)) {
                    ex.countAsCommand(commands);
                }
                if (Route.methodIs(ex, HttpMethod.POST)) {
                    command(ex, door);
                }
            }
            default -> Route.notFound(ex);
        }
    }

    private void command(ServerExchange ex, int door) {
        try {
            double data = JsonBody.parse(ex.body(), COMMAND_FIELDS).requireNumber("data");
            if (data != 0.0 && data != 1.0) {
                throw new ApiException(400, "data", "field 'data' must be 1.0 (open) or 0.0 (close), found " + data);
            }
            Replies.whenDone(ex, world.call(a -> {
                a.commands().door(door, data == 1.0);
                a.publishDoor(door);
                return DoorView.of(a.world().door(door));
            }));
        } catch (ApiException e) {
            ex.error(e);
        }
    }
}
