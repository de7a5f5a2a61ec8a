package eu.brain.iot.robotsim.cli;

import eu.brain.iot.robotsim.world.MapGenerator;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** {@code generate}: writes a large warehouse map (docking, storage, doors, dense unload area). */
@Command(name = "generate", sortOptions = false, usageHelpWidth = 120,
        customSynopsis = "java -jar robot-sim.jar generate [options]",
        description = "Writes a large warehouse map: docking, storage, doors, a dense unload area.",
        footer = "Example: java -jar robot-sim.jar generate --robots 10000 --width 400 --height 150 --out big.map")
final class GenerateCommand implements Callable<Integer> {
    @Spec
    private CommandSpec spec;

    private int width = 200;
    private int height = 100;
    private int robots = 1000;
    private int carts = 2000;
    private Integer doors;
    private long seed = 1;

    @Option(names = "--out", paramLabel = "FILE", description = "where to write the map (default: standard output)",
            order = 7)
    private Path out;

    @Option(names = {"--help", "-h"}, usageHelp = true, description = "show this help", order = 8)
    private boolean help;

    @Option(names = "--width", paramLabel = "N", description = "cells across (default 200)", order = 1)
    void width(String v) {
        width = Values.wholeInt(spec, "--width", v, 7, 5000);
    }

    @Option(names = "--height", paramLabel = "N", description = "cells down (default 100)", order = 2)
    void height(String v) {
        height = Values.wholeInt(spec, "--height", v, 12, 5000);
    }

    @Option(names = "--robots", paramLabel = "N", description = "robots in the docking area (default 1000)", order = 3)
    void robots(String v) {
        robots = Values.wholeInt(spec, "--robots", v, 0, 1_000_000);
    }

    @Option(names = "--carts", paramLabel = "N", description = "carts in the unload area (default 2000)", order = 4)
    void carts(String v) {
        carts = Values.wholeInt(spec, "--carts", v, 0, 1_000_000);
    }

    @Option(names = "--doors", paramLabel = "N",
            description = "doors between corridor and unload area (default width/40, at least 1)", order = 5)
    void doors(String v) {
        doors = Values.wholeInt(spec, "--doors", v, 1, 10_000);
    }

    @Option(names = "--seed", paramLabel = "N", description = "which cart slots are filled (default 1)", order = 6)
    void seed(String v) {
        seed = Values.whole(spec, "--seed", v, Long.MIN_VALUE, Long.MAX_VALUE);
    }

    @Override
    public Integer call() throws UsageException, IOException {
        int doorCount = doors != null ? doors : Math.max(1, width / 40);
        String text;
        try {
            String name = "generated-" + width + "x" + height + "-" + robots + "r";
            text = MapGenerator.text(name, width, height, robots, carts, doorCount, seed);
        } catch (IllegalArgumentException e) {
            throw new UsageException(e.getMessage());
        }
        PrintWriter printed = spec.commandLine().getOut();
        if (out == null) {
            printed.print(text);
        } else {
            try {
                Files.writeString(out, text, StandardCharsets.UTF_8);
            } catch (NoSuchFileException e) {
                throw new IOException("--out: cannot write '" + out + "': no such folder", e);
            } catch (IOException e) {
                throw new IOException("--out: cannot write '" + out + "': " + e.getMessage(), e);
            }
            printed.println("wrote " + out + ": " + width + "x" + height + ", " + robots + " robots, " + carts
                    + " carts, " + doorCount + " doors");
        }
        printed.flush();
        return 0;
    }
}
