package eu.brain.iot.scenario;

import eu.brain.iot.robotsim.world.MapFormatException;
import eu.brain.iot.robotsim.world.MapGenerator;
import eu.brain.iot.robotsim.world.MapParser;
import eu.brain.iot.robotsim.world.WarehouseMap;
import java.io.IOException;

/** The warehouse a run asked for: the paper's, a map file, or a generated one. Stateless. */
final class Warehouses {
    private Warehouses() {
    }

    /** @throws UsageException when the map file cannot be read or the generated warehouse cannot be made */
    static WarehouseMap of(Options o) throws UsageException {
        try {
            if (o.map() != null) {
                return MapParser.parse(o.map());
            }
            if (o.generate() != null) {
                Options.Generate g = o.generate();
                return MapGenerator.generate(g.width(), g.height(), g.robots(), g.carts(), g.doors(), o.seed());
            }
            return WarehouseMap.paper();
        } catch (MapFormatException e) {
            throw new UsageException("--map: " + e.getMessage());
        } catch (IOException e) {
            throw new UsageException("--map " + o.map() + ": cannot read it: " + e.getMessage());
        } catch (IllegalArgumentException e) {
            throw new UsageException("--generate: " + e.getMessage());
        }
    }
}
