package eu.brain.iot.robotsim.http;

import com.fasterxml.jackson.databind.JsonNode;
import eu.brain.iot.robotsim.WorldThread;
import eu.brain.iot.robotsim.fault.FaultFieldException;
import eu.brain.iot.robotsim.fault.FaultSettings;
import eu.brain.iot.robotsim.fault.FaultTable;
import io.netty.handler.codec.http.HttpMethod;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.ToIntFunction;

/**
 * {@code /admin/step} (manual stepping) and {@code /admin/faults[/{robot}]} (fault injection at run time).
 * Faults never apply to these endpoints.
 */
final class AdminApi {
    static final int MAX_STEPS_PER_REQUEST = 100_000;

    private final WorldThread world;
    private final FaultTable faults;
    private final List<String> robotIds;
    private final ToIntFunction<String> robotIndex;

    AdminApi(WorldThread world, FaultTable faults, List<String> robotIds, ToIntFunction<String> robotIndex) {
        this.world = world;
        this.faults = faults;
        this.robotIds = robotIds;
        this.robotIndex = robotIndex;
    }

    /** @param rest the path segments after {@code admin} */
    void handle(ServerExchange ex, List<String> rest) {
        try {
            if (rest.size() == 1 && rest.get(0).equals("step")) {
                if (Route.methodIs(ex, HttpMethod.POST)) {
                    step(ex);
                }
            } else if (!rest.isEmpty() && rest.get(0).equals("faults") && rest.size() <= 2) {
                if (rest.size() == 1) {
                    fleetFaults(ex);
                } else {
                    robotFaults(ex, rest.get(1));
                }
            } else {
                Route.notFound(ex);
            }
        } catch (ApiException e) {
            ex.error(e);
        }
    }

    private void step(ServerExchange ex) throws ApiException {
        JsonBody body = JsonBody.parse(ex.body(), Set.of("steps"));
        int steps = body.has("steps") ? body.requireInt("steps") : 1;
        if (steps < 1 || steps > MAX_STEPS_PER_REQUEST) {
            throw new ApiException(400, "steps", "field 'steps' must be 1.." + MAX_STEPS_PER_REQUEST
                    + ", found " + steps);
        }
        Replies.whenDone(ex, world.step(steps).thenApply(step -> Map.of("step", step)));
    }

    private void fleetFaults(ServerExchange ex) throws ApiException {
        if (!Route.methodIs(ex, HttpMethod.GET, HttpMethod.POST, HttpMethod.DELETE)) {
            return;
        }
        if (ex.method().equals(HttpMethod.POST)) {
            faults.setFleet(patch(faults.fleet(), ex.body()));
        } else if (ex.method().equals(HttpMethod.DELETE)) {
            faults.clear();
        }
        ex.json(200, describe());
    }

    private void robotFaults(ServerExchange ex, String id) throws ApiException {
        int robot = robotIndex.applyAsInt(id);
        if (robot < 0) {
            throw new ApiException(404, null, "unknown robot '" + id + "'");
        }
        if (!Route.methodIs(ex, HttpMethod.GET, HttpMethod.POST, HttpMethod.DELETE)) {
            return;
        }
        if (ex.method().equals(HttpMethod.POST)) {
            faults.setOwn(robot, patch(faults.effective(robot), ex.body()));
        } else if (ex.method().equals(HttpMethod.DELETE)) {
            faults.setOwn(robot, null);
        }
        Map<String, Object> doc = new LinkedHashMap<>();
        doc.put("robot", id);
        doc.put("own", faults.own(robot) != null);
        doc.put("effective", faults.effective(robot));
        ex.json(200, doc);
    }

    private static FaultSettings patch(FaultSettings base, byte[] body) throws ApiException {
        JsonBody parsed = JsonBody.parse(body, Set.copyOf(FaultSettings.FIELDS));
        FaultSettings result = base;
        for (Iterator<Map.Entry<String, JsonNode>> it = parsed.node().fields(); it.hasNext(); ) {
            Map.Entry<String, JsonNode> field = it.next();
            JsonNode v = field.getValue();
            Object value = v.isNumber() ? v.numberValue() : v.isBoolean() ? (Object) v.booleanValue() : v;
            try {
                result = result.with(field.getKey(), value);
            } catch (FaultFieldException e) {
                throw new ApiException(400, e.field(), e.getMessage() + ", found " + v);
            }
        }
        return result;
    }

    private Map<String, Object> describe() {
        Map<String, Object> doc = new LinkedHashMap<>();
        doc.put("fleet", faults.fleet());
        Map<String, FaultSettings> own = new LinkedHashMap<>();
        for (int i = 0; i < robotIds.size(); i++) {
            FaultSettings f = faults.own(i);
            if (f != null) {
                own.put(robotIds.get(i), f);
            }
        }
        doc.put("robots", own);
        return doc;
    }
}
