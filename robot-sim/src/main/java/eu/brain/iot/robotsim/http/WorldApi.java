package eu.brain.iot.robotsim.http;

import eu.brain.iot.robotsim.WorldThread;
import eu.brain.iot.robotsim.view.Json;
import eu.brain.iot.robotsim.view.WorldDocument;
import io.netty.handler.codec.http.HttpMethod;
import java.util.List;
import java.util.Map;

/** {@code GET /} (what is here), {@code GET /world} and {@code GET /world/counters}. */
final class WorldApi {
    private final WorldThread world;
    private final byte[] index;
    private final long stepMillis;
    private final CommandCounter commands;
    private final CommandOriginLog origins;

    WorldApi(WorldThread world, Map<String, Object> index, long stepMillis, CommandCounter commands,
             CommandOriginLog origins) {
        this.commands = commands;
        this.origins = origins;
        this.world = world;
        this.index = Json.bytes(index);
        this.stepMillis = stepMillis;
    }

    void index(ServerExchange ex) {
        if (Route.methodIs(ex, HttpMethod.GET)) {
            ex.json(200, index);
        }
    }

    /** @param rest the path segments after {@code world} */
    void handle(ServerExchange ex, List<String> rest) {
        if (rest.isEmpty()) {
            if (Route.methodIs(ex, HttpMethod.GET)) {
                Replies.whenDone(ex, world.call(a -> Json.bytes(WorldDocument.world(a.world(), stepMillis, commands.snapshot(),
                        origins.snapshot()))));
            }
        } else if (rest.size() == 1 && rest.get(0).equals("counters")) {
            if (Route.methodIs(ex, HttpMethod.GET)) {
                Replies.whenDone(ex, world.call(a -> Json.bytes(WorldDocument.counters(a.world(), stepMillis, commands.snapshot()))));
            }
        } else {
            Route.notFound(ex);
        }
    }
}
