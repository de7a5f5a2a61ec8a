package eu.brain.iot.edge.integration;

import eu.brain.iot.robotsim.world.MapFormatException;
import eu.brain.iot.robotsim.world.MapParser;
import eu.brain.iot.robotsim.world.WarehouseMap;

/** Warehouses with other devices than the paper's (3 robots, door1): for the tests of a change of fleet. */
public final class OtherFleets {

    private OtherFleets() {
    }

    /** Two robots and two doors: robot3 of the paper's warehouse is missing, door2 is new. */
    public static WarehouseMap twoRobotsTwoDoors() {
        try {
            return MapParser.parse("two-robots-two-doors", String.join("\n",
                    "name: two-robots-two-doors",
                    "map:",
                    "##########",
                    "#dRdR....#",
                    "#........#",
                    "####D##D##",
                    "#uuCuuuuu#",
                    "##########"));
        } catch (MapFormatException e) {
            throw new IllegalStateException(e.getMessage(), e);
        }
    }
}
