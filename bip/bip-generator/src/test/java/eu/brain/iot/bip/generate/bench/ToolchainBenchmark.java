package eu.brain.iot.bip.generate.bench;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;

import eu.brain.iot.bip.SyntheticModel;
import eu.brain.iot.bip.check.Checker;
import eu.brain.iot.bip.check.Workspace;
import eu.brain.iot.bip.diag.Diagnostics;
import eu.brain.iot.bip.generate.Generator;
import eu.brain.iot.bip.generate.JavaFile;

/**
 * Times parse, check and generate of a large synthetic model (default 5,000 lines), the way the CLI runs them:
 * the first run in a fresh JVM (what a user waits for) and the median of later runs (warm). Prints one line per
 * phase. Usage (from the repository root, after {@code mvn -pl bip/bip-generator -am test-compile}):
 * <pre>java -cp bip/bip-lang/target/classes:bip/bip-lang/target/test-classes:bip/bip-generator/target/classes:\
 *   bip/bip-generator/target/test-classes eu.brain.iot.bip.generate.bench.ToolchainBenchmark [lines] [--write FILE]</pre>
 */
public final class ToolchainBenchmark {

    private ToolchainBenchmark() {
    }

    public static void main(String[] args) throws Exception {
        int lines = args.length > 0 && !args[0].startsWith("--") ? Integer.parseInt(args[0]) : 5000;
        String model = SyntheticModel.of(lines, 42);
        int actualLines = model.split("\n", -1).length - 1;
        int write = Arrays.asList(args).indexOf("--write");
        if (write >= 0) {
            Files.writeString(Path.of(args[write + 1]), model, StandardCharsets.UTF_8);
            System.out.println("wrote " + actualLines + " lines to " + args[write + 1]);
            return;
        }
        System.out.printf("model: %d lines, %d characters; %d cores, %s%n", actualLines, model.length(),
                Runtime.getRuntime().availableProcessors(), System.getProperty("java.vm.version"));
        long[] first = runOnce(model);
        System.out.printf("first run (cold JVM): parse %.1f ms, check %.1f ms, generate %.1f ms, total %.1f ms%n",
                first[0] / 1e6, first[1] / 1e6, first[2] / 1e6, (first[0] + first[1] + first[2]) / 1e6);
        int runs = 20;
        long[][] warm = new long[3][runs];
        for (int i = 0; i < runs; i++) {
            long[] t = runOnce(model);
            for (int k = 0; k < 3; k++) {
                warm[k][i] = t[k];
            }
        }
        long[] total = new long[runs];
        for (int i = 0; i < runs; i++) {
            total[i] = warm[0][i] + warm[1][i] + warm[2][i];
        }
        System.out.printf("warm (median of %d): parse %.1f ms, check %.1f ms, generate %.1f ms, total %.1f ms (max %.1f ms)%n",
                runs, median(warm[0]) / 1e6, median(warm[1]) / 1e6, median(warm[2]) / 1e6, median(total) / 1e6,
                Arrays.stream(total).max().getAsLong() / 1e6);
    }

    private static long[] runOnce(String model) {
        Diagnostics diagnostics = new Diagnostics();
        Workspace ws = new Workspace(List.of(), diagnostics);
        long t0 = System.nanoTime();
        ws.addSource("synthetic.bip", model);
        long t1 = System.nanoTime();
        Checker.check(ws);
        long t2 = System.nanoTime();
        List<JavaFile> files = new Generator(ws, null).generate();
        long t3 = System.nanoTime();
        if (diagnostics.hasErrors() || files.isEmpty()) {
            throw new IllegalStateException("the benchmark model does not check: " + diagnostics);
        }
        return new long[] {t1 - t0, t2 - t1, t3 - t2};
    }

    private static long median(long[] values) {
        long[] sorted = values.clone();
        Arrays.sort(sorted);
        return sorted[sorted.length / 2];
    }
}
