package eu.brain.iot.edge.impl;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;

/** The command line of {@link PollBenchmark}. */
final class PollBenchmarkOptions {
    List<Integer> robots = List.of(100, 1_000, 10_000);
    int warmup = 20;
    int duration = 30;
    long periodMillis = 500;
    long timeoutMillis = 1_000;
    int connections = 64;
    int ioThreads = 1;
    double moving = 0.1;
    long seed = 1;
    int nodes = 1;
    Path simJar;
    int simIoThreads;
    String simJavaOpts = "";
    int width;
    int height;

    /** @return the options, or {@code null} for --help */
    static PollBenchmarkOptions parse(String[] args) {
        PollBenchmarkOptions o = new PollBenchmarkOptions();
        String jar = null;
        for (int i = 0; i < args.length; i++) {
            String flag = args[i];
            if (flag.equals("--help") || flag.equals("-h")) {
                return null;
            }
            if (i + 1 >= args.length) {
                throw new IllegalArgumentException(flag + " needs a value");
            }
            String v = args[++i];
            switch (flag) {
                case "--robots" -> {
                    List<Integer> sizes = new ArrayList<>();
                    for (String part : v.split(",")) {
                        sizes.add(number(flag, part.replace("_", ""), 1, 1_000_000));
                    }
                    o.robots = sizes;
                }
                case "--warmup" -> o.warmup = number(flag, v, 0, 3_600);
                case "--duration" -> o.duration = number(flag, v, 1, 3_600);
                case "--period-ms" -> o.periodMillis = number(flag, v, 1, 3_600_000);
                case "--timeout-ms" -> o.timeoutMillis = number(flag, v, 1, 3_600_000);
                case "--connections" -> o.connections = number(flag, v, 1, 10_000);
                case "--io-threads" -> o.ioThreads = number(flag, v, 1, 64);
                case "--moving" -> {
                    try {
                        o.moving = Double.parseDouble(v);
                    } catch (NumberFormatException e) {
                        o.moving = -1;
                    }
                    if (!(o.moving >= 0 && o.moving <= 1)) {
                        throw new IllegalArgumentException("--moving must be a share 0..1, found '" + v + "'");
                    }
                }
                case "--seed" -> o.seed = number(flag, v, 0, Integer.MAX_VALUE);
                case "--nodes" -> o.nodes = number(flag, v, 1, 64);
                case "--sim-jar" -> jar = v;
                case "--sim-io-threads" -> o.simIoThreads = number(flag, v, 1, 64);
                case "--sim-java-opts" -> o.simJavaOpts = v;
                case "--width" -> o.width = number(flag, v, 10, 10_000);
                case "--height" -> o.height = number(flag, v, 10, 10_000);
                default -> throw new IllegalArgumentException("unknown option " + flag);
            }
        }
        if ((o.width > 0) != (o.height > 0)) {
            throw new IllegalArgumentException("--width and --height go together");
        }
        o.simJar = simJar(jar);
        return o;
    }

    private static Path simJar(String given) {
        if (given != null) {
            Path p = Paths.get(given);
            if (!Files.isRegularFile(p)) {
                throw new IllegalArgumentException("--sim-jar: no file " + p.toAbsolutePath());
            }
            return p.toAbsolutePath();
        }
        for (String candidate : List.of("robot-sim/target/robot-sim.jar", "../robot-sim/target/robot-sim.jar")) {
            Path p = Paths.get(candidate);
            if (Files.isRegularFile(p)) {
                return p.toAbsolutePath();
            }
        }
        throw new IllegalArgumentException("no robot-sim/target/robot-sim.jar: build it (mvn -B -q -pl robot-sim "
                + "package -DskipTests) or give --sim-jar");
    }

    private static int number(String flag, String v, int min, int max) {
        try {
            int n = Integer.parseInt(v.trim());
            if (n >= min && n <= max) {
                return n;
            }
        } catch (NumberFormatException e) {
            // below
        }
        throw new IllegalArgumentException(flag + " must be a whole number " + min + ".." + max + ", found '" + v
                + "'");
    }
}
