package eu.brain.iot.robotsim.world;

/** A world driven directly on the test thread (its owner here), for tests of the rules without HTTP. */
final class Sim {
    final World world;
    final StepEngine engine;
    final Commands commands;
    final boolean[] offline;

    Sim(WarehouseMap map, SimRules rules) {
        world = new World(map, rules);
        offline = new boolean[world.robotCount()];
        engine = new StepEngine(world, i -> offline[i]);
        commands = new Commands(world);
    }

    static Sim of(String mapText) {
        return of(mapText, SimRules.DEFAULT);
    }

    static Sim of(String mapText, SimRules rules) {
        try {
            return new Sim(MapParser.parse("test.map", mapText), rules);
        } catch (MapFormatException e) {
            throw new IllegalArgumentException(e);
        }
    }

    Robot robot(String id) {
        return world.robot(world.robotIndex(id));
    }

    int index(String id) {
        return world.robotIndex(id);
    }

    Mission goTo(String id, int x, int y) {
        try {
            return commands.goTo(index(id), x, y);
        } catch (CommandRejectedException e) {
            throw new AssertionError(e);
        }
    }

    void step(int n) {
        for (int i = 0; i < n; i++) {
            engine.step();
        }
    }

    Cart cart(String id) {
        for (int i = 0; i < world.cartCount(); i++) {
            if (world.cart(i).id().equals(id)) {
                return world.cart(i);
            }
        }
        throw new IllegalArgumentException(id);
    }
}
