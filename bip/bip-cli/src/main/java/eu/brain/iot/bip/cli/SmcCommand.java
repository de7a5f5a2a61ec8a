package eu.brain.iot.bip.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.Callable;
import java.util.function.Supplier;

import eu.brain.iot.bip.diag.Diagnostics;
import eu.brain.iot.bip.model.Pos;
import eu.brain.iot.bip.smc.RequirementsCheck;
import eu.brain.iot.bip.smc.RequirementsFile;
import eu.brain.iot.bip.smc.SmcSession;
import eu.brain.iot.bip.smc.engine.PointResult;
import eu.brain.iot.bip.smc.engine.SmcOptions;
import eu.brain.iot.bip.smc.engine.SmcRunner;
import eu.brain.iot.bip.smc.query.Query;
import eu.brain.iot.bip.smc.query.QueryException;
import eu.brain.iot.bip.smc.report.Reports;
import eu.brain.iot.bip.smc.report.SvgPlot;
import eu.brain.iot.bip.smc.runtime.SimulationExterns;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code bip smc MODEL.bip --property 'P=? [...]'}: statistical model checking from the command line. Exit code 0
 * when every query was answered and no requirement is refuted, 1 for model or query errors or a refuted
 * requirement, 2 for a bad command line.
 */
@Command
final class SmcCommand implements Callable<Integer> {

    static final String USAGE = """
            usage: bip smc FILE... [-I DIR]... [--root COMPOUND] (--property QUERY | --properties FILE)...
                       [--epsilon E] [--delta D] [--alpha A] [--beta B] [--indifference I] [--test sprt|fixed]
                       [--seed S] [--threads N] [--max-steps N] [--engine compiled|interpreted]
                       [--externs CLASS [--cp PATH]] [--csv FILE] [--svg FILE] [--report DIR] [--quiet]
              QUERY       P=? [ φ ], P>=θ [ φ ] or P<=θ [ φ ], optionally 'for x = from:to:step, ...'
              --properties a requirements file (see bip/README): 'set' lines and 'NAME: QUERY' lines
              --externs   the simulation of the model's extern functions (implements
                          eu.brain.iot.bip.smc.runtime.SimulationExterns), found on --cp
              defaults: epsilon = delta = alpha = beta = indifference = 0.01, sprt, seed 1, every core,
                        traces as long as each formula's horizon, the compiled engine
            """;

    private final PrintStream out;
    private final PrintStream err;

    @Parameters(arity = "0..*")
    private List<Path> files = new ArrayList<>();
    @Option(names = "-I")
    private List<Path> includes = new ArrayList<>();
    @Option(names = "--root")
    private String root;
    @Option(names = "--property")
    private List<String> properties = new ArrayList<>();
    @Option(names = "--properties")
    private List<Path> propertyFiles = new ArrayList<>();
    @Option(names = "--externs")
    private String externs;
    @Option(names = "--cp")
    private List<String> classpathOptions = new ArrayList<>();
    @Option(names = "--csv")
    private Path csv;
    @Option(names = "--svg")
    private Path svg;
    @Option(names = "--report")
    private Path report;
    @Option(names = "--quiet")
    private boolean quiet;
    @Option(names = {"-h", "--help"})
    private boolean help;

    /** The model checker's options ({@link SmcOptions#with}), as given: checked there, in this order. */
    @Option(names = "--epsilon")
    private String epsilon;
    @Option(names = "--delta")
    private String delta;
    @Option(names = "--alpha")
    private String alpha;
    @Option(names = "--beta")
    private String beta;
    @Option(names = "--indifference")
    private String indifference;
    @Option(names = "--test")
    private String test;
    @Option(names = "--seed")
    private String seed;
    @Option(names = "--threads")
    private String threads;
    @Option(names = "--max-steps")
    private String maxSteps;
    @Option(names = "--engine")
    private String engine;

    SmcCommand(PrintStream out, PrintStream err) {
        this.out = out;
        this.err = err;
    }

    private Map<String, String> options() {
        Map<String, String> options = new LinkedHashMap<>();
        String[][] given = {{"epsilon", epsilon}, {"delta", delta}, {"alpha", alpha}, {"beta", beta},
            {"indifference", indifference}, {"test", test}, {"seed", seed}, {"threads", threads},
            {"max-steps", maxSteps}, {"engine", engine}};
        for (String[] o : given) {
            if (o[1] != null) {
                options.put(o[0], o[1]);
            }
        }
        return options;
    }

    @Override
    public Integer call() {
        if (help) {
            out.print(USAGE);
            return Exit.OK;
        }
        try {
            return check();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            err.println("bip: interrupted");
            return Exit.INTERNAL;
        }
    }

    private int check() throws InterruptedException {
        if (files.isEmpty() || properties.isEmpty() && propertyFiles.isEmpty()) {
            err.println("bip: smc needs a model file and at least one --property or --properties\n" + USAGE);
            return Exit.USAGE;
        }
        List<Path> classpath = new ArrayList<>();
        for (String entries : classpathOptions) {
            for (String p : entries.split(java.io.File.pathSeparator)) {
                classpath.add(Path.of(p));
            }
        }
        List<Path> modelPath = ModelCommand.withFolders(files, includes);
        String root = this.root;
        String externs = this.externs;
        Diagnostics diagnostics = new Diagnostics();
        Pos externsPos = new Pos("--externs", 1, 1);
        List<RequirementsFile> requirementFiles = new ArrayList<>();
        for (Path p : propertyFiles) {
            requirementFiles.add(RequirementsFile.read(p, diagnostics));
            RequirementsFile last = requirementFiles.get(requirementFiles.size() - 1);
            if (root == null && last.settings().containsKey("root")) {
                root = last.settings().get("root").value();
            }
            if (externs == null && last.settings().containsKey("externs")) {
                externs = last.settings().get("externs").value();
                externsPos = last.settings().get("externs").pos();
            }
        }
        SmcOptions smc = SmcOptions.defaults();
        for (RequirementsFile f : requirementFiles) {
            for (Map.Entry<String, RequirementsFile.Setting> s : f.settings().entrySet()) {
                if (!s.getKey().equals("root") && !s.getKey().equals("externs")) {
                    try {
                        smc = smc.with(s.getKey(), s.getValue().value());
                    } catch (IllegalArgumentException e) {
                        diagnostics.error(s.getValue().pos(), e.getMessage());
                    }
                }
            }
        }
        for (Map.Entry<String, String> o : options().entrySet()) {
            try {
                smc = smc.with(o.getKey(), o.getValue());
            } catch (IllegalArgumentException e) {
                err.println("bip: --" + o.getKey() + ": " + e.getMessage());
                return Exit.USAGE;
            }
        }
        Optional<SmcSession> session = diagnostics.hasErrors() ? Optional.empty()
                : SmcSession.load(files, modelPath, root, diagnostics);
        List<Query> queries = new ArrayList<>();
        if (session.isPresent()) {
            for (int i = 0; i < properties.size(); i++) {
                String origin = properties.size() == 1 ? "--property" : "--property#" + (i + 1);
                try {
                    queries.add(session.get().parse(null, properties.get(i), new Pos(origin, 1, 1), ""));
                } catch (QueryException e) {
                    diagnostics.error(e.pos(), e.getMessage());
                }
            }
            for (RequirementsFile f : requirementFiles) {
                for (RequirementsFile.Entry e : f.entries()) {
                    try {
                        queries.add(session.get().parse(e.name(), e.text(), e.textPos(), e.justification()));
                    } catch (QueryException x) {
                        diagnostics.error(x.pos(), x.getMessage());
                    }
                }
            }
        }
        if (diagnostics.hasErrors() || session.isEmpty()) {
            diagnostics.sorted().forEach(err::println);
            err.println("bip: " + diagnostics.errorCount() + " error(s)");
            return Exit.PROBLEMS;
        }
        diagnostics.sorted().forEach(err::println);
        Supplier<SimulationExterns> simulation = externs == null ? () -> SimulationExterns.NONE
                : RequirementsCheck.simulationExterns(externs, externsPos, classpath, diagnostics);
        if (diagnostics.hasErrors()) {
            diagnostics.sorted().forEach(err::println);
            return Exit.PROBLEMS;
        }
        TerminalProgress listener = quiet || System.console() == null ? null : new TerminalProgress(err);
        RequirementsCheck.Outcome outcome;
        try {
            outcome = RequirementsCheck.check(session.get(), queries, smc, simulation, classpath,
                    report, listener);
        } catch (RequirementsCheck.Failure e) {
            TerminalProgress.clear(listener);
            err.println("bip: " + e.getMessage());
            return Exit.PROBLEMS;
        }
        TerminalProgress.clear(listener);
        // the report ends its last line, so what follows on stderr (the same terminal) starts a line of its own
        String text = outcome.report();
        out.print(text.isEmpty() || text.endsWith("\n") ? text : text + "\n");
        out.flush();
        try {
            if (csv != null) {
                Files.writeString(csv, Reports.csv(outcome.results()), StandardCharsets.UTF_8);
            }
            if (svg != null) {
                List<PointResult> swept = outcome.results().stream().filter(r -> r.params().length > 0).toList();
                if (swept.isEmpty()) {
                    err.println("bip: --svg: no query is swept ('for x = from:to:step'), so there is nothing to plot");
                } else {
                    Files.writeString(svg, SvgPlot.plot("P against " + swept.get(0).query().sweeps().get(0).name(),
                            swept), StandardCharsets.UTF_8);
                }
            }
        } catch (IOException e) {
            err.println("bip: cannot write " + e.getMessage());
            return Exit.PROBLEMS;
        }
        if (!outcome.refuted().isEmpty()) {
            err.println("bip: " + outcome.refuted().size() + " requirement(s) refuted");
            return Exit.PROBLEMS;
        }
        return Exit.OK;
    }

    /** Live progress on the terminal (stderr), redrawn in place; called from the thread running the queries. */
    private static final class TerminalProgress implements SmcRunner.Listener {
        private final PrintStream err;

        TerminalProgress(PrintStream err) {
            this.err = err;
        }

        /** Clears the progress line (when there is one), so the next message starts on a clean line. */
        static void clear(TerminalProgress progress) {
            if (progress != null) {
                progress.err.print("\r\033[K");
                progress.err.flush();
            }
        }

        @Override
        public void progress(Query query, double[] params, long done, long target, long successes, long elapsed) {
            double seconds = elapsed / 1e9;
            double rate = done / Math.max(seconds, 1e-9);
            String left = target < 0 || done == 0 ? "until the test decides"
                    : String.format(Locale.ROOT, "%.1f s left", (target - done) / Math.max(rate, 1e-9));
            StringBuilder point = new StringBuilder();
            for (int i = 0; i < params.length; i++) {
                point.append(i == 0 ? " (" : ", ").append(query.sweeps().get(i).name()).append('=')
                        .append(Reports.number(params[i])).append(i == params.length - 1 ? ")" : "");
            }
            err.printf(Locale.ROOT, "\r\033[K%s%s: %,d%s traces, %,.0f/s, estimate %.4f, %s", query.name(), point, done,
                    target < 0 ? "" : String.format(Locale.ROOT, "/%,d", target), rate,
                    done == 0 ? 0.0 : (double) successes / done, left);
            err.flush();
        }
    }
}
