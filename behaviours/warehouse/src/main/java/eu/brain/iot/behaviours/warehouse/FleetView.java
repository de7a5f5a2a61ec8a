package eu.brain.iot.behaviours.warehouse;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;

import eu.brain.iot.edge.model.api.DeviceModel;
import eu.brain.iot.edge.model.api.ProviderSnapshot;
import eu.brain.iot.edge.model.api.ResourceStatus;
import eu.brain.iot.edge.model.api.ResourceValue;

/**
 * What the behaviours' extern functions read of the fleet, from the edge's device model only (never from the fleet
 * itself): robots, doors, carts and the map (the edge reads carts and map from the fleet's world). Each call reads
 * the model afresh; the parsed map is kept while its rows stay the same. Thread-safe: the model is, and the cached
 * map is one immutable pair in a volatile field.
 */
public final class FleetView {

    /** A door: where it stands and its state ({@code closed}, {@code opening}, {@code open}, {@code closing}). */
    public record DoorState(String id, Cell cell, String state) {
    }

    /** A cart: where it stands and who carries it ({@code null}: on the floor). */
    public record CartState(String id, Cell cell, String carriedBy) {
    }

    private record CachedGrid(String rows, Grid grid) {
    }

    private final DeviceModel model;
    private volatile CachedGrid grid;

    public FleetView(DeviceModel model) {
        this.model = model;
    }

    /** @return the robot, or empty when the edge does not know it (yet) */
    public Optional<RobotState> robot(String id) {
        return model.provider(id).filter(p -> "robot".equals(p.kind())).flatMap(FleetView::robot);
    }

    /**
     * @return the node that polls and commands the device, as another node's report names it (the edge's
     *         {@code fabric/node} resource); empty for a device of this node's own (or unknown)
     * @since 2.6
     */
    public Optional<String> ownerNode(String deviceId) {
        return model.provider(deviceId).map(p -> p.value("fabric", "node")).filter(String.class::isInstance)
                .map(String.class::cast);
    }

    /** @return every robot the edge has polled at least once, by id */
    public List<RobotState> robots() {
        List<RobotState> all = new ArrayList<>();
        for (ProviderSnapshot p : model.providers()) {
            if ("robot".equals(p.kind())) {
                robot(p).ifPresent(all::add);
            }
        }
        return all;
    }

    public List<DoorState> doors() {
        List<DoorState> all = new ArrayList<>();
        for (ProviderSnapshot p : model.providers()) {
            Integer x = integer(p, "position", "x");
            Integer y = integer(p, "position", "y");
            if ("door".equals(p.kind()) && x != null && y != null) {
                all.add(new DoorState(p.id(), new Cell(x, y), text(p, "door", "state")));
            }
        }
        return all;
    }

    public List<CartState> carts() {
        List<CartState> all = new ArrayList<>();
        for (ProviderSnapshot p : model.providers()) {
            Integer x = integer(p, "position", "x");
            Integer y = integer(p, "position", "y");
            if ("cart".equals(p.kind()) && x != null && y != null) {
                all.add(new CartState(p.id(), new Cell(x, y), text(p, "cart", "carriedBy")));
            }
        }
        return all;
    }

    /** @return the cells of the carts no robot carries: walls for a robot carrying a cart, which cannot pass under one */
    public Set<Cell> cartsOnTheFloor() {
        Set<Cell> cells = new HashSet<>();
        for (CartState c : carts()) {
            if (c.carriedBy() == null) {
                cells.add(c.cell());
            }
        }
        return cells;
    }

    /** @return the warehouse's map, or empty until the edge has read the fleet's world */
    public Optional<Grid> grid() {
        Optional<ResourceValue> rows = model.resource("warehouse", "map", "rows");
        if (rows.isEmpty() || !(rows.get().value() instanceof String text)) {
            return Optional.empty();
        }
        CachedGrid cached = grid;
        if (cached == null || !cached.rows().equals(text)) {
            cached = new CachedGrid(text, Grid.parse(text));
            grid = cached;
        }
        return Optional.of(cached.grid());
    }

    private static Optional<RobotState> robot(ProviderSnapshot p) {
        Integer x = integer(p, "position", "x");
        Integer y = integer(p, "position", "y");
        if (x == null || y == null) {
            return Optional.empty();
        }
        Integer area = integer(p, "position", "area");
        Integer detect = integer(p, "state", "detect");
        Integer gx = integer(p, "mission", "goalX");
        Integer gy = integer(p, "mission", "goalY");
        Object id = p.value("mission", "id");
        return Optional.of(new RobotState(p.id(), new Cell(x, y), text(p, "position", "heading"),
                area == null ? 0 : area, "running".equals(text(p, "state", "state")), detect == null ? 0 : detect,
                text(p, "cart", "cart"), id instanceof Number n ? n.longValue() : null, text(p, "mission", "type"),
                text(p, "mission", "state"), gx == null || gy == null ? null : new Cell(gx, gy),
                p.status() != ResourceStatus.UNREACHABLE && p.status() != ResourceStatus.STALE));
    }

    private static Integer integer(ProviderSnapshot p, String service, String resource) {
        return p.value(service, resource) instanceof Number n ? n.intValue() : null;
    }

    private static String text(ProviderSnapshot p, String service, String resource) {
        Object v = p.value(service, resource);
        return v == null ? null : v.toString();
    }
}
