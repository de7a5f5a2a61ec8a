package eu.brain.iot.robotsim.http;

import eu.brain.iot.robotsim.WorldThread;
import eu.brain.iot.robotsim.fault.FaultAction;
import eu.brain.iot.robotsim.fault.FaultSettings;
import eu.brain.iot.robotsim.fault.FaultTable;
import eu.brain.iot.robotsim.view.MissionView;
import eu.brain.iot.robotsim.view.ViewPublisher;
import eu.brain.iot.robotsim.world.Mission;
import eu.brain.iot.robotsim.world.MissionType;
import eu.brain.iot.robotsim.world.Robot;
import io.netty.handler.codec.http.HttpMethod;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * {@code /{robot}/robot_local_control/...}: the state poll (served from the pre-serialized view, never waiting for
 * the world thread) and the mission components, whose orders run on the world thread. Faults set for the robot
 * apply to every request here, before the request is looked at.
 */
final class RobotApi {
    private static final Set<String> GOAL_FIELDS = Set.of("x", "y");
    private static final Set<String> CANCEL_FIELDS = Set.of("id");

    private final WorldThread world;
    private final ViewPublisher views;
    private final FaultTable faults;
    private final CommandCounter commands;
    private final CommandOriginLog origins;

    RobotApi(WorldThread world, ViewPublisher views, FaultTable faults, CommandCounter commands,
             CommandOriginLog origins) {
        this.origins = origins;
        this.world = world;
        this.views = views;
        this.faults = faults;
        this.commands = commands;
    }

    /** A mission order: POST .../{component}/add or .../cancel (what the fleet counts as commands). */
    private static boolean isCommand(ServerExchange ex, List<String> rest) {
        if (!ex.method().equals(HttpMethod.POST) || rest.isEmpty()) {
            return false;
        }
        String last = rest.get(rest.size() - 1);
        return last.equals("add") || last.equals("cancel");
    }

    /** @param rest the path segments after {@code robot_local_control} */
    void handle(ServerExchange ex, int robot, String id, List<String> rest) {
        String node = CommanderHeader.UNKNOWN;
        if (isCommand(ex, rest)) {
            ex.countAsCommand(commands);
            try {
                node = CommanderHeader.node(ex.commander());
            } catch (ApiException e) {
                ex.error(e);
                return;
            }
        }
        FaultSettings f = faults.effective(robot);
        ex.delay(f.latencyMs());
        FaultAction action = faults.next(robot, f);
        switch (action) {
            case OFFLINE -> {
                ex.error(503, null, "robot " + id + " is offline", null);
                return;
            }
            case DROP -> {
                ex.drop();
                return;
            }
            case ERROR_500 -> {
                ex.error(500, null, "injected fault: robot " + id + " failed to answer", null);
                return;
            }
            case MALFORMED -> ex.malformed();
            default -> {
                // answer normally
            }
        }
        if (rest.size() == 1 && rest.get(0).equals("state")) {
            if (Route.methodIs(ex, HttpMethod.GET)) {
                ex.json(200, views.robot(robot).json());
            }
            return;
        }
        List<String> component = !rest.isEmpty() && rest.get(0).equals("NavigationComponent")
                ? rest.subList(1, rest.size()) : rest;
        MissionType type = component.size() == 2 ? typeOf(component.get(0)) : null;
        if (type == null) {
            Route.notFound(ex);
            return;
        }
        try {
            switch (component.get(1)) {
                case "add" -> add(ex, robot, id, type, node);
                case "cancel" -> cancel(ex, robot, id, type, node);
                case "query_state" -> query(ex, robot, id, type);
                default -> Route.notFound(ex);
            }
        } catch (ApiException e) {
            ex.error(e);
        }
    }

    private static MissionType typeOf(String component) {
        for (MissionType t : MissionType.values()) {
            if (t.component().equals(component)) {
                return t;
            }
        }
        return null;
    }

    /**
     * @param node the commanding node: recorded when the robot takes the order (on the world thread, after the
     *             command passed); an order refused changes nothing, its origin included
     */
    private void add(ServerExchange ex, int robot, String id, MissionType type, String node) throws ApiException {
        if (!Route.methodIs(ex, HttpMethod.POST)) {
            return;
        }
        if (type == MissionType.GOTO) {
            JsonBody body = JsonBody.parse(ex.body(), GOAL_FIELDS);
            int x = body.requireInt("x");
            int y = body.requireInt("y");
            Replies.whenDone(ex, world.call(a -> {
                Mission m = a.commands().goTo(robot, x, y);
                origins.record(id, node);
                a.publishRobot(robot);
                return added(id, type, m);
            }));
        } else {
            JsonBody.parse(ex.body(), Set.of());
            Replies.whenDone(ex, world.call(a -> {
                Mission m = type == MissionType.PICK ? a.commands().pick(robot) : a.commands().place(robot);
                origins.record(id, node);
                a.publishRobot(robot);
                return added(id, type, m);
            }));
        }
    }

    private static Map<String, Object> added(String robot, MissionType type, Mission m) {
        Map<String, Object> doc = new LinkedHashMap<>();
        doc.put("robot", robot);
        doc.put("component", type.component());
        doc.put("mission", MissionView.of(m));
        return doc;
    }

    private void cancel(ServerExchange ex, int robot, String id, MissionType type, String node)
            throws ApiException {
        if (!Route.methodIs(ex, HttpMethod.POST)) {
            return;
        }
        Long missionId = JsonBody.parse(ex.body(), CANCEL_FIELDS).optionalLong("id");
        Replies.whenDone(ex, world.call(a -> {
            List<Mission> cancelled = a.commands().cancel(robot, type, missionId);
            origins.record(id, node);
            a.publishRobot(robot);
            Map<String, Object> doc = new LinkedHashMap<>();
            doc.put("robot", id);
            doc.put("component", type.component());
            doc.put("cancelled", cancelled.stream().map(MissionView::of).toList());
            return doc;
        }));
    }

    private void query(ServerExchange ex, int robot, String id, MissionType type) throws ApiException {
        if (!Route.methodIs(ex, HttpMethod.GET, HttpMethod.POST)) {
            return;
        }
        JsonBody.parse(ex.body(), Set.of());
        Replies.whenDone(ex, world.call(a -> {
            Robot r = a.world().robot(robot);
            Mission current = r.current() != null && r.current().type() == type ? r.current() : null;
            Map<String, Object> doc = new LinkedHashMap<>();
            doc.put("robot", id);
            doc.put("component", type.component());
            doc.put("current", MissionView.of(current));
            doc.put("queued", r.queued().stream().filter(m -> m.type() == type).map(MissionView::of).toList());
            doc.put("history", r.history().stream().filter(m -> m.type() == type).map(MissionView::of).toList());
            return doc;
        }));
    }
}
