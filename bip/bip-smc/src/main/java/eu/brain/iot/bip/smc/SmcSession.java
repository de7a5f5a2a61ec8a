package eu.brain.iot.bip.smc;

import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.function.Supplier;

import eu.brain.iot.bip.check.ModelSet;
import eu.brain.iot.bip.diag.Diagnostics;
import eu.brain.iot.bip.model.Pos;
import eu.brain.iot.bip.smc.engine.SmcOptions;
import eu.brain.iot.bip.smc.engine.SmcRunner;
import eu.brain.iot.bip.smc.query.Names;
import eu.brain.iot.bip.smc.query.Query;
import eu.brain.iot.bip.smc.query.QueryException;
import eu.brain.iot.bip.smc.query.QueryParser;
import eu.brain.iot.bip.smc.runtime.SimulationExterns;
import eu.brain.iot.bip.smc.sim.SimulationException;
import eu.brain.iot.bip.smc.sim.SystemSimulator;
import eu.brain.iot.bip.system.SystemModel;

/**
 * The statistical model checker's entry point: a checked system (the root compound of the given files, flattened),
 * queries parsed against it, and a runner over a simulator compiled for those queries. The CLI ({@code smc}), the
 * Maven goal ({@code bip:verify-requirements}, through {@link RequirementsCheck}) and the benchmark use it.
 */
public final class SmcSession {

    private final SystemModel system;
    private final Names names;

    private SmcSession(SystemModel system) {
        this.system = system;
        this.names = new Names(system);
    }

    /**
     * Loads and checks the files (and what they use from {@code modelPath}) and flattens the root compound.
     *
     * @return empty when there are errors (in {@code diagnostics})
     */
    public static Optional<SmcSession> load(List<Path> files, List<Path> modelPath, String root,
            Diagnostics diagnostics) {
        ModelSet models = ModelSet.load(files, modelPath, diagnostics, root);
        if (!models.check()) {
            return Optional.empty();
        }
        return SystemModel.build(models.workspace(), root, diagnostics).filter(s -> !diagnostics.hasErrors())
                .map(SmcSession::new);
    }

    /** A session over a system already built (tests). */
    public static SmcSession of(SystemModel system) {
        return new SmcSession(system);
    }

    public SystemModel system() {
        return system;
    }

    /**
     * @param name the requirement's name (null: the query text)
     * @param origin where the text starts, for messages ({@code --property:1:1} on the command line)
     */
    public Query parse(String name, String text, Pos origin, String justification) throws QueryException {
        return QueryParser.parse(name, text, origin, names, justification);
    }

    public Query parse(String text) throws QueryException {
        return parse(null, text, new Pos("<query>", 1, 1), "");
    }

    /** Generates, compiles and loads the simulation of the system with the queries' propositions (or interprets). */
    public SystemSimulator simulator(List<Query> queries, SmcOptions options, Supplier<SimulationExterns> externs,
            List<Path> classpath) throws SimulationException {
        return SystemSimulator.of(system, queries, options.engine(), externs, classpath);
    }

    /** A runner for the queries on a simulator made for them. */
    public SmcRunner runner(SystemSimulator simulator, List<Query> queries, SmcOptions options) {
        return new SmcRunner(simulator, queries, options);
    }
}
