package eu.brain.iot.bip.smc.sim;

import java.lang.reflect.Constructor;
import java.lang.reflect.InvocationTargetException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Supplier;

import eu.brain.iot.bip.check.Type;
import eu.brain.iot.bip.diag.Diagnostic;
import eu.brain.iot.bip.diag.Diagnostics;
import eu.brain.iot.bip.generate.JavaFile;
import eu.brain.iot.bip.generate.SimulationWriter;
import eu.brain.iot.bip.smc.query.Query;
import eu.brain.iot.bip.smc.query.Term;
import eu.brain.iot.bip.smc.runtime.Builtins;
import eu.brain.iot.bip.smc.runtime.SimulatedSystem;
import eu.brain.iot.bip.smc.runtime.SimulationExterns;
import eu.brain.iot.bip.system.SystemModel;

/**
 * Makes the simulated systems the sampling threads use, for a system and the queries to check on it: by default
 * compiled ({@link SimulationWriter}'s Java, compiled in process and loaded in a fresh class loader, the queries'
 * atomic propositions included), or interpreted ({@link InterpretedSystem}, the reference). Immutable after
 * construction; {@link #create} may be called from any thread.
 */
public final class SystemSimulator {

    /** How traces are produced. */
    public enum Engine { COMPILED, INTERPRETED }

    private static final AtomicInteger CLASSES = new AtomicInteger();

    private final SystemModel system;
    private final List<Query> queries;
    private final Engine engine;
    private final Supplier<SimulationExterns> externs;
    private final int[] apOffset;
    private final int[] paramOffset;
    private final int paramCount;
    private final Constructor<? extends SimulatedSystem> driver;
    private final long compileNanos;

    private SystemSimulator(SystemModel system, List<Query> queries, Engine engine, Supplier<SimulationExterns> externs,
            List<Path> classpath, ClassLoader parent) throws SimulationException {
        this.system = system;
        this.queries = List.copyOf(queries);
        this.engine = engine;
        this.externs = externs;
        this.apOffset = new int[queries.size()];
        this.paramOffset = new int[queries.size()];
        int aps = 0;
        int params = 0;
        for (int q = 0; q < queries.size(); q++) {
            apOffset[q] = aps;
            paramOffset[q] = params;
            aps += queries.get(q).propositions().size();
            params += queries.get(q).sweeps().size();
        }
        this.paramCount = params;
        long start = System.nanoTime();
        this.driver = engine == Engine.COMPILED ? compile(classpath, parent) : null;
        this.compileNanos = System.nanoTime() - start;
    }

    /**
     * @param externs makes the simulation of the model's extern functions, one per sampling thread
     * @param classpath where the classes {@code externs} needs are (for the compiled engine), may be empty
     */
    public static SystemSimulator of(SystemModel system, List<Query> queries, Engine engine,
            Supplier<SimulationExterns> externs, List<Path> classpath) throws SimulationException {
        return new SystemSimulator(system, queries, engine, externs, classpath, SystemSimulator.class.getClassLoader());
    }

    /**
     * As {@link #of(SystemModel, List, Engine, Supplier, List)}, the compiled classes' loader having {@code parent}
     * (tests: a parent that already holds classes of the same names, as a class path with the deployed jars does).
     */
    static SystemSimulator of(SystemModel system, List<Query> queries, Engine engine,
            Supplier<SimulationExterns> externs, List<Path> classpath, ClassLoader parent) throws SimulationException {
        return new SystemSimulator(system, queries, engine, externs, classpath, parent);
    }

    public Engine engine() {
        return engine;
    }

    /** @return the time spent generating and compiling the Java (0 for the interpreter) */
    public long compileNanos() {
        return compileNanos;
    }

    public SystemModel system() {
        return system;
    }

    /** @return the index of the first atomic proposition of query {@code q} in a created system's {@code ap} */
    public int apOffset(int q) {
        return apOffset[q];
    }

    /** A new simulated system (for one thread) evaluating query {@code q}'s propositions with these parameters. */
    public SimulatedSystem create(int q, double[] params) {
        SimulationExterns simulation = externs.get();
        if (engine == Engine.INTERPRETED) {
            List<Term> all = new ArrayList<>();
            queries.forEach(x -> all.addAll(x.propositions()));
            double[] global = new double[paramCount];
            System.arraycopy(params, 0, global, paramOffset[q], params.length);
            return new InterpretedSystem(system, shift(all, q), global, simulation);
        }
        double[] global = new double[paramCount];
        System.arraycopy(params, 0, global, paramOffset[q], params.length);
        try {
            return driver.newInstance(simulation, global);
        } catch (InstantiationException | IllegalAccessException | InvocationTargetException e) {
            throw new IllegalStateException("cannot create the compiled system: " + e, e);
        }
    }

    /** The interpreter reads parameters by their global index, like the compiled driver. */
    private List<Term> shift(List<Term> all, int q) {
        List<Term> shifted = new ArrayList<>();
        int query = 0;
        for (int i = 0; i < all.size(); i++) {
            while (query + 1 < queries.size() && i >= apOffset[query + 1]) {
                query++;
            }
            shifted.add(shiftParams(all.get(i), paramOffset[query]));
        }
        return shifted;
    }

    private static Term shiftParams(Term t, int offset) {
        if (t instanceof Term.Param p) {
            return new Term.Param(p.index() + offset, p.name(), p.type());
        } else if (t instanceof Term.Unary u) {
            return new Term.Unary(u.op(), shiftParams(u.operand(), offset), u.type());
        } else if (t instanceof Term.Binary b) {
            return new Term.Binary(b.op(), shiftParams(b.left(), offset), shiftParams(b.right(), offset), b.type());
        }
        return t;
    }

    private Constructor<? extends SimulatedSystem> compile(List<Path> classpath, ClassLoader parent)
            throws SimulationException {
        Diagnostics diagnostics = new Diagnostics();
        SimulationWriter writer = new SimulationWriter(system, diagnostics, Builtins::isBuiltin);
        List<JavaFile> files = new ArrayList<>(writer.atomFiles());
        List<String> propositions = new ArrayList<>();
        for (int q = 0; q < queries.size(); q++) {
            for (Term t : queries.get(q).propositions()) {
                propositions.add(java(t, writer, paramOffset[q]));
            }
        }
        String name = "System" + CLASSES.incrementAndGet();
        JavaFile driverFile = writer.driver("eu.brain.iot.bip.smc.generated", name, propositions);
        files.add(driverFile);
        if (diagnostics.hasErrors()) {
            StringBuilder s = new StringBuilder();
            for (Diagnostic d : diagnostics.errors()) {
                s.append(s.length() == 0 ? "" : "\n").append(d);
            }
            throw new SimulationException(s.toString());
        }
        try {
            ClassLoader loader = RuntimeCompiler.compile(files, classpath, parent);
            Class<? extends SimulatedSystem> type = loader.loadClass(driverFile.qualifiedName())
                    .asSubclass(SimulatedSystem.class);
            return type.getConstructor(SimulationExterns.class, double[].class);
        } catch (RuntimeCompiler.CompileException e) {
            throw new SimulationException(e.getMessage());
        } catch (ReflectiveOperationException e) {
            throw new SimulationException("cannot load the compiled system: " + e);
        }
    }

    /** The Java of a proposition: direct reads of the atoms' fields. */
    static String java(Term t, SimulationWriter w, int paramOffset) {
        if (t instanceof Term.Lit l) {
            return l.type().kind() == Type.Kind.FLOAT ? Double.toString((Double) l.value()) : l.value().toString();
        } else if (t instanceof Term.Data d) {
            return w.dataRead(d.atom(), d.name());
        } else if (t instanceof Term.At a) {
            return w.placeRead(a.atom(), a.place());
        } else if (t instanceof Term.Param p) {
            String v = "params[" + (p.index() + paramOffset) + "]";
            return p.type().kind() == Type.Kind.INT ? "((int) " + v + ")" : v;
        } else if (t instanceof Term.Unary u) {
            return "(" + u.op().symbol + java(u.operand(), w, paramOffset) + ")";
        }
        Term.Binary b = (Term.Binary) t;
        return "(" + java(b.left(), w, paramOffset) + " " + b.op().symbol + " " + java(b.right(), w, paramOffset)
                + ")";
    }
}
