package eu.brain.iot.robotsim.http;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/** Sends each request to the endpoint class that owns its path. Immutable; shared by all I/O threads. */
final class Router {
    private final Map<String, Integer> robots;
    private final Map<String, Integer> doors;
    private final RobotApi robotApi;
    private final DoorApi doorApi;
    private final AdminApi adminApi;
    private final WorldApi worldApi;

    Router(Map<String, Integer> robots, Map<String, Integer> doors, RobotApi robotApi, DoorApi doorApi,
           AdminApi adminApi, WorldApi worldApi) {
        this.robots = Map.copyOf(robots);
        this.doors = Map.copyOf(doors);
        this.robotApi = robotApi;
        this.doorApi = doorApi;
        this.adminApi = adminApi;
        this.worldApi = worldApi;
    }

    void route(ServerExchange ex) {
        List<String> segments = segments(ex.path());
        if (segments.isEmpty()) {
            worldApi.index(ex);
            return;
        }
        String first = segments.get(0);
        List<String> rest = segments.subList(1, segments.size());
        switch (first) {
            case "world" -> worldApi.handle(ex, rest);
            case "admin" -> adminApi.handle(ex, rest);
            default -> device(ex, first, rest);
        }
    }

    private void device(ServerExchange ex, String id, List<String> rest) {
        String kind = rest.isEmpty() ? "" : rest.get(0);
        List<String> after = rest.isEmpty() ? rest : rest.subList(1, rest.size());
        if (kind.equals("robot_local_control")) {
            Integer robot = robots.get(id);
            if (robot == null) {
                ex.error(404, null, "unknown robot '" + id + "'", null);
            } else {
                robotApi.handle(ex, robot, id, after);
            }
        } else if (kind.equals("door_controller")) {
            Integer door = doors.get(id);
            if (door == null) {
                ex.error(404, null, "unknown door '" + id + "'", null);
            } else {
                doorApi.handle(ex, door, after);
            }
        } else {
            Route.notFound(ex);
        }
    }

    static List<String> segments(String path) {
        List<String> out = new ArrayList<>(4);
        int start = 0;
        int n = path.length();
        while (start < n) {
            int slash = path.indexOf('/', start);
            int end = slash < 0 ? n : slash;
            if (end > start) {
                out.add(path.substring(start, end));
            }
            start = end + 1;
        }
        return out;
    }
}
