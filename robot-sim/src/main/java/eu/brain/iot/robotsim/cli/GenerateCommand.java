package eu.brain.iot.robotsim.cli;

import eu.brain.iot.robotsim.world.MapGenerator;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Set;

/** {@code generate}: writes a large warehouse map (docking, storage, doors, dense unload area). */
final class GenerateCommand {
    static final String USAGE = """
            Usage: java -jar robot-sim.jar generate [options]
              --width N    cells across (default 200)
              --height N   cells down (default 100)
              --robots N   robots in the docking area (default 1000)
              --carts N    carts in the unload area (default 2000)
              --doors N    doors between corridor and unload area (default width/40, at least 1)
              --seed N     which cart slots are filled (default 1)
              --out FILE   where to write the map (default: standard output)
            Example: java -jar robot-sim.jar generate --robots 10000 --width 400 --height 150 --out big.map
            """;

    private GenerateCommand() {
    }

    static void run(String[] args, PrintStream out) throws UsageException, IOException {
        Flags f = Flags.parse(args, Set.of("width", "height", "robots", "carts", "doors", "seed", "out"), Set.of());
        int width = f.intValue("width", 200, 7, 5000);
        int height = f.intValue("height", 100, 12, 5000);
        int robots = f.intValue("robots", 1000, 0, 1_000_000);
        int carts = f.intValue("carts", 2000, 0, 1_000_000);
        int doors = f.intValue("doors", Math.max(1, width / 40), 1, 10_000);
        long seed = f.longValue("seed", 1, Long.MIN_VALUE, Long.MAX_VALUE);
        String text;
        try {
            String name = "generated-" + width + "x" + height + "-" + robots + "r";
            text = MapGenerator.text(name, width, height, robots, carts, doors, seed);
        } catch (IllegalArgumentException e) {
            throw new UsageException(e.getMessage());
        }
        String file = f.string("out", null);
        if (file == null) {
            out.print(text);
        } else {
            Files.writeString(Path.of(file), text, StandardCharsets.UTF_8);
            out.println("wrote " + file + ": " + width + "x" + height + ", " + robots + " robots, " + carts
                    + " carts, " + doors + " doors");
        }
    }
}
