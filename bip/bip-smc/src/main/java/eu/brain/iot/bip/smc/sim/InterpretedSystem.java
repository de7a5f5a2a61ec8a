package eu.brain.iot.bip.smc.sim;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import eu.brain.iot.bip.interp.AtomRun;
import eu.brain.iot.bip.interp.SystemRun;
import eu.brain.iot.bip.model.AtomType;
import eu.brain.iot.bip.model.DataDecl;
import eu.brain.iot.bip.smc.query.Term;
import eu.brain.iot.bip.smc.runtime.Builtins;
import eu.brain.iot.bip.smc.runtime.SimulatedSystem;
import eu.brain.iot.bip.smc.runtime.SimulationExterns;
import eu.brain.iot.bip.smc.runtime.TraceRandom;
import eu.brain.iot.bip.system.SystemModel;
import eu.brain.iot.bip.system.SystemModel.AtomInstance;

/**
 * The reference simulation: the interpreter ({@link SystemRun}, {@link AtomRun}) stepping a system with the
 * statistical model checker's semantics (candidates: internal steps, then ports that are not exported, then
 * interactions, one chosen uniformly; built-ins drawn from the trace's random source in execution order). Slow;
 * the compiled driver must agree with it step by step. Owned by one thread.
 */
final class InterpretedSystem implements SimulatedSystem, Term.State {

    private final SystemModel system;
    private final List<Term> propositions;
    private final double[] params;
    private final SimulationExterns simulation;
    private final TraceRandom random = new TraceRandom();
    private final List<AtomRun> atoms = new ArrayList<>();
    private SystemRun run;
    private String last = "";

    InterpretedSystem(SystemModel system, List<Term> propositions, double[] params, SimulationExterns simulation) {
        this.system = system;
        this.propositions = propositions;
        this.params = params;
        this.simulation = simulation;
    }

    @Override
    public void reset(long seed) {
        random.seed(seed);
        run = new SystemRun(system, (name, types, result, args) -> Builtins.call(name, types, result, args, random,
                simulation));
        atoms.clear();
        for (AtomInstance a : system.atoms()) {
            atoms.add(run.atom(a.path()));
        }
        last = "";
    }

    /** One candidate: an internal step of an atom (index), or one of the interpreter's candidates. */
    private record Choice(int internal, SystemRun.Candidate candidate) {
    }

    @Override
    public boolean step() {
        List<Choice> choices = new ArrayList<>();
        for (int i = 0; i < atoms.size(); i++) {
            if (atoms.get(i).internalEnabled()) {
                choices.add(new Choice(i, null));
            }
        }
        run.candidates().forEach(c -> choices.add(new Choice(-1, c)));
        if (choices.isEmpty()) {
            return false;
        }
        Choice c = choices.size() == 1 ? choices.get(0) : choices.get(random.nextInt(choices.size()));
        // named before it runs, like the compiled driver: a step that fails is the one lastStep() names
        if (c.internal() >= 0) {
            last = "internal " + system.atoms().get(c.internal()).path();
            atoms.get(c.internal()).internalStep();
        } else {
            last = c.candidate().connector() == null
                    ? c.candidate().ports().get(0).atom() + "." + c.candidate().ports().get(0).port()
                    : c.candidate().toString();
            run.execute(c.candidate());
        }
        return true;
    }

    @Override
    public boolean ap(int index) {
        return (Boolean) Term.eval(propositions.get(index), this);
    }

    @Override
    public String lastStep() {
        return last;
    }

    @Override
    public String state() {
        StringBuilder s = new StringBuilder();
        for (int i = 0; i < atoms.size(); i++) {
            AtomRun a = atoms.get(i);
            List<String> places = new ArrayList<>();
            for (AtomType.Place p : a.type().places()) {
                if (a.marking().contains(p.name())) {
                    places.add(p.name());
                }
            }
            Map<String, Object> data = new LinkedHashMap<>();
            for (DataDecl d : a.type().data()) {
                data.put(d.name(), a.get(d.name()));
            }
            s.append(system.atoms().get(i).path()).append(" [").append(String.join(", ", places)).append("] ")
                    .append(data).append('\n');
        }
        return s.toString();
    }

    @Override
    public Object data(int atom, String name) {
        return atoms.get(atom).get(name);
    }

    @Override
    public boolean at(int atom, String place) {
        return atoms.get(atom).marking().contains(place);
    }

    @Override
    public double param(int index) {
        return params[index];
    }
}
