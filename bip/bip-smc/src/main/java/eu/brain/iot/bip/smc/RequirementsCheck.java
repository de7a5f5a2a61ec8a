package eu.brain.iot.bip.smc;

import java.io.IOException;
import java.net.MalformedURLException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.function.Supplier;

import eu.brain.iot.bip.diag.Diagnostics;
import eu.brain.iot.bip.model.Pos;
import eu.brain.iot.bip.smc.engine.PointResult;
import eu.brain.iot.bip.smc.engine.SmcOptions;
import eu.brain.iot.bip.smc.engine.SmcRunner;
import eu.brain.iot.bip.smc.query.Query;
import eu.brain.iot.bip.smc.query.QueryException;
import eu.brain.iot.bip.smc.report.Reports;
import eu.brain.iot.bip.smc.report.SvgPlot;
import eu.brain.iot.bip.smc.runtime.SimulationExterns;
import eu.brain.iot.bip.smc.sim.SimulationException;
import eu.brain.iot.bip.smc.sim.SystemSimulator;

/**
 * Checks a requirements file on a model and writes the report: the entry point of the Maven goal
 * {@code bip:verify-requirements} and of the CLI's {@code smc --properties}. Problems with the model, the file or a
 * query go to the diagnostics ({@code file:line:col}); a refuted requirement is in {@link Outcome#refuted()}.
 */
public final class RequirementsCheck {

    /**
     * @param root the system's compound type when the file has no {@code set root} (null: the default)
     * @param reportDirectory where report.txt, report.csv and the plots go, or null for none
     * @param overrides options that win over the file's {@code set} lines (e.g. threads, seed)
     * @param classpath where the class named by {@code set externs} is found
     */
    public record Request(List<Path> modelFiles, List<Path> modelPath, String root, Path requirements,
            Path reportDirectory, Map<String, String> overrides, List<Path> classpath) {
    }

    /** The results, in file order, and the report's text. */
    public record Outcome(List<PointResult> results, String report, SmcOptions options, long compileNanos) {
        public List<PointResult> refuted() {
            return results.stream().filter(PointResult::refuted).toList();
        }
    }

    /** A trace failed or the system cannot be simulated: one line for the user. */
    public static final class Failure extends Exception {
        private static final long serialVersionUID = 1L;

        public Failure(String message) {
            super(message);
        }
    }

    private RequirementsCheck() {
    }

    /** @return the outcome, or empty when there are errors in {@code diagnostics} */
    public static Optional<Outcome> run(Request request, Diagnostics diagnostics, SmcRunner.Listener listener)
            throws Failure, InterruptedException {
        RequirementsFile file = RequirementsFile.read(request.requirements(), diagnostics);
        if (diagnostics.hasErrors()) {
            return Optional.empty();
        }
        // the file's own root is the more specific: a plugin-level <root> is usually the deployed system's
        String root = file.settings().containsKey("root") ? file.settings().get("root").value() : request.root();
        SmcOptions options = SmcOptions.defaults();
        for (Map.Entry<String, RequirementsFile.Setting> s : file.settings().entrySet()) {
            if (s.getKey().equals("root") || s.getKey().equals("externs")) {
                continue;
            }
            try {
                options = options.with(s.getKey(), s.getValue().value());
            } catch (IllegalArgumentException e) {
                diagnostics.error(s.getValue().pos(), e.getMessage());
            }
        }
        for (Map.Entry<String, String> o : request.overrides().entrySet()) {
            try {
                options = options.with(o.getKey(), o.getValue());
            } catch (IllegalArgumentException e) {
                diagnostics.error(new Pos("<options>", 1, 1), e.getMessage());
            }
        }
        RequirementsFile.Setting externs = file.settings().get("externs");
        Supplier<SimulationExterns> simulation = externs == null ? () -> SimulationExterns.NONE
                : simulationExterns(externs.value(), externs.pos(), request.classpath(), diagnostics);
        Optional<SmcSession> session = SmcSession.load(request.modelFiles(), request.modelPath(), root, diagnostics);
        if (session.isEmpty() || diagnostics.hasErrors()) {
            return Optional.empty();
        }
        List<Query> queries = new ArrayList<>();
        for (RequirementsFile.Entry e : file.entries()) {
            try {
                queries.add(session.get().parse(e.name(), e.text(), e.textPos(), e.justification()));
            } catch (QueryException x) {
                diagnostics.error(x.pos(), x.getMessage());
            }
        }
        if (diagnostics.hasErrors()) {
            return Optional.empty();
        }
        return Optional.of(check(session.get(), queries, options, simulation, request.classpath(),
                request.reportDirectory(), listener));
    }

    /** Checks parsed queries and writes the report (when {@code reportDirectory} is not null). */
    public static Outcome check(SmcSession session, List<Query> queries, SmcOptions options,
            Supplier<SimulationExterns> simulation, List<Path> classpath, Path reportDirectory,
            SmcRunner.Listener listener) throws Failure, InterruptedException {
        SystemSimulator simulator;
        try {
            simulator = session.simulator(queries, options, simulation, classpath);
        } catch (SimulationException e) {
            throw new Failure(e.getMessage());
        }
        List<PointResult> results;
        try {
            results = session.runner(simulator, queries, options).runAll(listener);
        } catch (eu.brain.iot.bip.smc.engine.TraceFailureException e) {
            throw new Failure(e.getMessage());
        }
        String report = report(session, results, options, simulator);
        if (reportDirectory != null) {
            write(reportDirectory, report, results);
        }
        return new Outcome(results, report, options, simulator.compileNanos());
    }

    static String report(SmcSession session, List<PointResult> results, SmcOptions options,
            SystemSimulator simulator) {
        StringBuilder s = new StringBuilder();
        s.append("Statistical model checking of ").append(session.system().root().name()).append(" (")
                .append(session.system().atoms().size()).append(" atoms, ").append(session.system().connectors().size())
                .append(" connectors), engine ").append(simulator.engine().name().toLowerCase(Locale.ROOT))
                .append(String.format(Locale.ROOT, ", seed %d, epsilon %s, delta %s, alpha %s, beta %s, "
                        + "indifference %s, test %s%n%n", options.seed(), options.epsilon(), options.delta(),
                        options.alpha(), options.beta(), options.indifference(),
                        options.test().name().toLowerCase(Locale.ROOT)));
        s.append(Reports.table(results));
        for (PointResult r : results) {
            if (r.refuted()) {
                s.append('\n').append(refutation(r));
            }
        }
        return s.toString();
    }

    /** @return the sentence saying which requirement is refuted, its estimate and confidence */
    public static String refutation(PointResult r) {
        Query q = r.query();
        return String.format(Locale.ROOT, "%s:%d:%d: requirement %s REFUTED: %s%s; estimate %.4f, %.0f%% interval "
                + "[%.4f, %.4f] from %d traces (%s)%s%n", q.pos().file(), q.pos().line(), q.pos().column(), q.name(),
                q.text(), r.params().length == 0 ? "" : " at " + Reports.params(r), r.estimate(),
                100 * r.confidence(), r.lower(), r.upper(), r.samples(), r.method(),
                q.justification().isEmpty() ? "" : "\n  justification: " + q.justification());
    }

    private static void write(Path dir, String report, List<PointResult> results) throws Failure {
        try {
            Files.createDirectories(dir);
            Files.writeString(dir.resolve("report.txt"), report, StandardCharsets.UTF_8);
            Files.writeString(dir.resolve("report.csv"), Reports.csv(results), StandardCharsets.UTF_8);
            List<PointResult> swept = results.stream().filter(r -> !r.query().sweeps().isEmpty()).toList();
            if (!swept.isEmpty()) {
                Files.writeString(dir.resolve("sweeps.svg"), SvgPlot.plot("swept queries", swept),
                        StandardCharsets.UTF_8);
                for (String name : swept.stream().map(r -> r.query().name()).distinct().toList()) {
                    List<PointResult> mine = swept.stream().filter(r -> r.query().name().equals(name)).toList();
                    Files.writeString(dir.resolve(name.replaceAll("[^\\w.-]", "_") + ".svg"),
                            SvgPlot.plot(mine.get(0).query().text(), mine), StandardCharsets.UTF_8);
                }
            }
        } catch (IOException e) {
            throw new Failure("cannot write the report under " + dir + ": " + e.getMessage());
        }
    }

    /**
     * Loads the simulation of a model's extern functions: a class implementing {@link SimulationExterns} with a
     * public no-argument constructor, found on {@code classpath} or the model checker's own class path.
     *
     * @return a supplier of one instance per sampling thread (NONE after an error, reported at {@code pos})
     */
    public static Supplier<SimulationExterns> simulationExterns(String className, Pos pos, List<Path> classpath,
            Diagnostics diagnostics) {
        RequirementsFile.Setting setting = new RequirementsFile.Setting(className, pos);
        try {
            List<URL> urls = new ArrayList<>();
            for (Path p : classpath) {
                urls.add(p.toUri().toURL());
            }
            ClassLoader loader = new URLClassLoader(urls.toArray(URL[]::new), RequirementsCheck.class.getClassLoader());
            Class<? extends SimulationExterns> type = loader.loadClass(setting.value())
                    .asSubclass(SimulationExterns.class);
            var constructor = type.getConstructor();
            constructor.newInstance();
            return () -> {
                try {
                    return constructor.newInstance();
                } catch (ReflectiveOperationException e) {
                    throw new IllegalStateException(e);
                }
            };
        } catch (ClassNotFoundException e) {
            diagnostics.error(setting.pos(), "class " + setting.value() + " not found on the class path " + classpath
                    + " (the simulation of the extern functions; compile it in the module's test classes)");
        } catch (ClassCastException e) {
            diagnostics.error(setting.pos(), "class " + setting.value() + " does not implement "
                    + SimulationExterns.class.getName());
        } catch (ReflectiveOperationException | MalformedURLException e) {
            diagnostics.error(setting.pos(), "cannot create " + setting.value() + " (it needs a public constructor "
                    + "without arguments): " + e);
        }
        return () -> SimulationExterns.NONE;
    }
}
