package eu.brain.iot.benchmarks;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * What to run and for how long. Defaults keep the whole run to about two to three minutes on 2 cores.
 *
 * @param contenders the buses to measure, in order
 * @param bundleDir where the contenders' bundle jars are
 * @param warmupRounds throughput rounds run and discarded before measuring, per consumer count
 * @param rounds measured throughput rounds; the median is reported
 * @param roundMillis the aimed duration of one throughput round; its event count is calibrated per bus
 * @param latencyRate events per second in the latency phase
 * @param latencyWarmupSeconds paced seconds run and discarded before the latency is recorded
 * @param latencySeconds paced seconds recorded
 * @param fork whether each contender runs in a JVM of its own (see {@link ForkedRun})
 * @param resultFile where a forked JVM writes its one result, {@code null} in the launching JVM
 */
record Settings(List<Contender> contenders, Path bundleDir, int warmupRounds, int rounds, long roundMillis,
        int latencyRate, int latencyWarmupSeconds, int latencySeconds, boolean fork, Path resultFile) {

    static final String USAGE = """
            usage: java -jar benchmarks/target/benchmarks.jar [options]
              --contenders a,b,...   buses to measure, in order (default: all): %s
              --warmup N             discarded throughput rounds per consumer count (default 3)
              --rounds N             measured throughput rounds, median reported (default 5)
              --round-ms N           aimed duration of one throughput round in ms (default 1000)
              --latency-rate N       paced events per second for latency (default 2000)
              --latency-warmup S     paced seconds discarded before recording (default 2)
              --latency-seconds S    paced seconds recorded (default 5)
              --bundles DIR          directory of the bundle jars (default: bundles/ next to benchmarks.jar)
              --fork yes|no          each contender in a fresh JVM with this JVM's options (default yes);
                                     no: all in this JVM, where a contender inherits the JIT profiles of the
                                     ones before it
            """;

    static Settings parse(String[] args, Path defaultBundleDir) {
        List<Contender> contenders = Contender.all();
        Path bundleDir = defaultBundleDir;
        int warmup = 3;
        int rounds = 5;
        long roundMillis = 1000;
        int rate = 2000;
        int latencyWarmup = 2;
        int latencySeconds = 5;
        boolean fork = true;
        Path resultFile = null;
        for (int i = 0; i < args.length; i++) {
            String option = args[i];
            if (i + 1 >= args.length) {
                throw new BenchmarkException("option " + option + " needs a value\n" + usage());
            }
            String value = args[++i];
            switch (option) {
                case "--contenders" -> contenders = contenders(value);
                case "--bundles" -> bundleDir = Path.of(value);
                case "--warmup" -> warmup = positive(option, value, 0);
                case "--rounds" -> rounds = positive(option, value, 1);
                case "--round-ms" -> roundMillis = positive(option, value, 10);
                case "--latency-rate" -> rate = positive(option, value, 1);
                case "--latency-warmup" -> latencyWarmup = positive(option, value, 0);
                case "--latency-seconds" -> latencySeconds = positive(option, value, 1);
                case "--fork" -> fork = yesNo(option, value);
                case ForkedRun.RESULT_OPTION -> resultFile = Path.of(value);
                default -> throw new BenchmarkException("unknown option " + option + "\n" + usage());
            }
        }
        return new Settings(contenders, bundleDir, warmup, rounds, roundMillis, rate, latencyWarmup, latencySeconds,
                fork && resultFile == null, resultFile);
    }

    private static boolean yesNo(String option, String value) {
        return switch (value) {
            case "yes" -> true;
            case "no" -> false;
            default -> throw new BenchmarkException(option + " takes yes or no, got '" + value + "'");
        };
    }

    private static List<Contender> contenders(String value) {
        List<Contender> chosen = new ArrayList<>();
        for (String key : value.split(",")) {
            chosen.add(Contender.all().stream().filter(c -> c.key().equals(key.trim())).findFirst()
                    .orElseThrow(() -> new BenchmarkException("unknown contender '" + key + "'; known: " + keys())));
        }
        return chosen;
    }

    private static int positive(String option, String value, int min) {
        try {
            int n = Integer.parseInt(value);
            if (n >= min) {
                return n;
            }
        } catch (NumberFormatException e) {
            // reported below
        }
        throw new BenchmarkException(option + " needs a whole number of at least " + min + ", got '" + value + "'");
    }

    private static String keys() {
        return String.join(",", Contender.all().stream().map(Contender::key).toList());
    }

    static boolean wantsHelp(String[] args) {
        return Arrays.asList(args).contains("--help") || Arrays.asList(args).contains("-h");
    }

    static String usage() {
        return USAGE.formatted(keys());
    }

    @Override
    public String toString() {
        return "warm-up rounds " + warmupRounds + ", measured rounds " + rounds + " of ~" + roundMillis
                + " ms; latency at " + latencyRate + " events/s: " + latencyWarmupSeconds + " s discarded, "
                + latencySeconds + " s recorded; contenders " + Arrays.toString(
                        contenders.stream().map(Contender::key).toArray())
                + (fork ? ", each in a JVM of its own" : ", all in this JVM");
    }
}
