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

/**
 * {@code bip smc MODEL.bip --property 'P=? [...]'}: statistical model checking from the command line. Exit code 0
 * when every query was answered and no requirement is refuted, 1 for model or query errors or a refuted
 * requirement, 2 for a bad command line.
 */
final class SmcCommand {

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

    private static final List<String> OPTIONS = List.of("epsilon", "delta", "alpha", "beta", "indifference", "test",
            "seed", "threads", "max-steps", "engine");

    private SmcCommand() {
    }

    static int run(String[] args, PrintStream out, PrintStream err) throws InterruptedException {
        if (List.of(args).contains("--help") || List.of(args).contains("-h")) {
            out.print(USAGE);
            return 0;
        }
        List<Path> files = new ArrayList<>();
        List<Path> includes = new ArrayList<>();
        List<String> properties = new ArrayList<>();
        List<Path> propertyFiles = new ArrayList<>();
        Map<String, String> options = new LinkedHashMap<>();
        String root = null;
        Path csv = null;
        Path svg = null;
        Path report = null;
        boolean quiet = false;
        String externs = null;
        List<Path> classpath = new ArrayList<>();
        for (int i = 1; i < args.length; i++) {
            String a = args[i];
            String key = a.startsWith("--") ? a.substring(2) : a;
            boolean valued = a.equals("-I") || OPTIONS.contains(key) || List.of("root", "property", "properties", "csv",
                    "svg", "report", "externs", "cp").contains(key) && a.startsWith("--");
            if (valued && i + 1 >= args.length) {
                err.println("bip: " + a + " needs a value\n" + USAGE);
                return 2;
            }
            if (a.equals("-I")) {
                includes.add(Path.of(args[++i]));
            } else if (a.equals("--quiet")) {
                quiet = true;
            } else if (a.startsWith("--") && OPTIONS.contains(key)) {
                options.put(key, args[++i]);
            } else if (a.equals("--root")) {
                root = args[++i];
            } else if (a.equals("--property")) {
                properties.add(args[++i]);
            } else if (a.equals("--properties")) {
                propertyFiles.add(Path.of(args[++i]));
            } else if (a.equals("--externs")) {
                externs = args[++i];
            } else if (a.equals("--cp")) {
                for (String p : args[++i].split(java.io.File.pathSeparator)) {
                    classpath.add(Path.of(p));
                }
            } else if (a.equals("--csv")) {
                csv = Path.of(args[++i]);
            } else if (a.equals("--svg")) {
                svg = Path.of(args[++i]);
            } else if (a.equals("--report")) {
                report = Path.of(args[++i]);
            } else if (a.startsWith("-")) {
                err.println("bip: unknown option " + a + "\n" + USAGE);
                return 2;
            } else {
                files.add(Path.of(a));
            }
        }
        if (files.isEmpty() || properties.isEmpty() && propertyFiles.isEmpty()) {
            err.println("bip: smc needs a model file and at least one --property or --properties\n" + USAGE);
            return 2;
        }
        for (Path f : files) {
            if (f.getParent() != null && !includes.contains(f.getParent())) {
                includes.add(f.getParent());
            }
        }
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
        for (Map.Entry<String, String> o : options.entrySet()) {
            try {
                smc = smc.with(o.getKey(), o.getValue());
            } catch (IllegalArgumentException e) {
                err.println("bip: --" + o.getKey() + ": " + e.getMessage());
                return 2;
            }
        }
        Optional<SmcSession> session = diagnostics.hasErrors() ? Optional.empty()
                : SmcSession.load(files, includes, root, diagnostics);
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
            return 1;
        }
        diagnostics.sorted().forEach(err::println);
        java.util.function.Supplier<SimulationExterns> simulation = externs == null ? () -> SimulationExterns.NONE
                : RequirementsCheck.simulationExterns(externs, externsPos, classpath, diagnostics);
        if (diagnostics.hasErrors()) {
            diagnostics.sorted().forEach(err::println);
            return 1;
        }
        SmcRunner.Listener listener = quiet || System.console() == null ? null : new TerminalProgress(err);
        RequirementsCheck.Outcome outcome;
        try {
            outcome = RequirementsCheck.check(session.get(), queries, smc, simulation, classpath,
                    report, listener);
        } catch (RequirementsCheck.Failure e) {
            err.println("bip: " + e.getMessage());
            return 1;
        }
        if (listener != null) {
            err.print("\r\033[K");
        }
        out.print(outcome.report());
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
            return 1;
        }
        if (!outcome.refuted().isEmpty()) {
            err.println("bip: " + outcome.refuted().size() + " requirement(s) refuted");
            return 1;
        }
        return 0;
    }

    /** Live progress on the terminal (stderr), redrawn in place; called from the thread running the queries. */
    private static final class TerminalProgress implements SmcRunner.Listener {
        private final PrintStream err;

        TerminalProgress(PrintStream err) {
            this.err = err;
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
