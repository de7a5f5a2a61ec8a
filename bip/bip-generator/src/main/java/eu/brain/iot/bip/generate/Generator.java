package eu.brain.iot.bip.generate;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

import eu.brain.iot.bip.check.ExprTyper;
import eu.brain.iot.bip.check.PackageScope;
import eu.brain.iot.bip.check.ResolvedCall;
import eu.brain.iot.bip.check.Workspace;
import eu.brain.iot.bip.diag.Diagnostics;
import eu.brain.iot.bip.model.AtomType;
import eu.brain.iot.bip.model.BipPackage;
import eu.brain.iot.bip.system.SystemModel;

/**
 * Generates Java for the workspace's own packages: per atom type a class and (when it calls any) an extern
 * interface; when a root compound exists, per instantiated atom type of an own package an OSGi smart behaviour,
 * and, when the root belongs to an own package, the system's event types. Expects a checked workspace.
 */
public final class Generator {

    private final Workspace workspace;
    private final String rootName;
    private final Diagnostics diagnostics;
    private final boolean strictBus;
    /** What the last {@link #generate()} wrote and did not write, and why: one line each, for the user. */
    private final List<String> summary = new ArrayList<>();
    /** The own atom types that got no behaviour because no root compound instantiates them. */
    private final List<String> withoutRoot = new ArrayList<>();

    /** Lenient: a system that cannot be realised on the bus still gets its atom classes (see below). */
    public Generator(Workspace workspace, String rootName) {
        this(workspace, rootName, false);
    }

    /**
     * @param strictBus whether a root compound that cannot be realised on the event bus (e.g. a hierarchical
     *        connector) is an error; when false it is reported as warnings, and only the atom classes and extern
     *        interfaces are generated
     */
    public Generator(Workspace workspace, String rootName, boolean strictBus) {
        this.workspace = workspace;
        this.rootName = rootName;
        this.diagnostics = workspace.diagnostics();
        this.strictBus = strictBus;
    }

    /** The Java names of one atom type's generated classes. */
    record AtomNames(String javaPackage, String atomClass, String externs, boolean hasExterns, String behaviour) {
    }

    public List<JavaFile> generate() {
        List<JavaFile> files = new ArrayList<>();
        Optional<SystemModel> system = SystemModel.build(workspace, rootName, diagnostics);
        Diagnostics bus = strictBus ? diagnostics : new Diagnostics();
        BusPlan plan = system.map(s -> new BusPlan(s, bus)).orElse(null);
        Map<AtomType, AtomNames> names = new HashMap<>();
        for (BipPackage pkg : workspace.packages()) {
            PackageScope scope = new PackageScope(workspace, pkg);
            ExprTyper typer = new ExprTyper(scope, new Diagnostics());
            String javaPackage = JavaNames.javaPackage(pkg);
            for (AtomType atom : pkg.atomTypes()) {
                List<ResolvedCall> calls = new ArrayList<>(AtomWriter.calls(atom, scope, typer));
                if (plan != null) {
                    calls.addAll(plan.connectorCalls(atom));
                }
                calls = ExternsWriter.distinct(calls, atom, diagnostics);
                String base = JavaNames.type(atom.name());
                AtomNames n = new AtomNames(javaPackage, base, base + "Externs", !calls.isEmpty(),
                        JavaNames.behaviourClass(base));
                names.put(atom, n);
                if (!workspace.isOwn(pkg.name())) {
                    continue;
                }
                files.add(new JavaFile(javaPackage, n.atomClass(),
                        new AtomWriter(atom, scope, typer, n.atomClass(), n.externs()).write(javaPackage, n.hasExterns())));
                if (n.hasExterns()) {
                    files.add(new JavaFile(javaPackage, n.externs(),
                            ExternsWriter.write(javaPackage, n.externs(), atom, calls, scope)));
                }
                summary.add(atom.name() + ": " + javaPackage + "." + n.atomClass() + " (atom class)" + (n.hasExterns()
                        ? ", " + n.externs() + " (its extern functions: implement this interface)"
                        : "; it calls no extern function, so no extern interface"));
            }
        }
        if (plan == null && !diagnostics.hasErrors()) {
            for (BipPackage pkg : workspace.ownPackages()) {
                for (AtomType atom : pkg.atomTypes()) {
                    withoutRoot.add(atom.name());
                    summary.add("no behaviour class for " + atom.name() + ": no root compound instantiates it (the "
                            + "files given declare no compound type and --root names none)");
                }
            }
            summary.add("no event types: they are generated with the root compound");
        }
        if (plan != null && !diagnostics.hasErrors()) {
            List<JavaFile> busFiles = busFiles(plan, system.get(), names, bus);
            if (!bus.hasErrors()) {
                files.addAll(busFiles);
            } else if (!strictBus) {
                for (var d : bus.errors()) {
                    diagnostics.warning(d.pos(), d.message() + " (so no smart behaviour or event type is generated "
                            + "for compound " + system.get().root().name() + "; the atom classes are)");
                }
                summary.add("no behaviour class or event type: compound " + system.get().root().name() + " cannot "
                        + "run on the event bus (see the warnings; --strict makes them errors)");
            }
        }
        if (diagnostics.hasErrors()) {
            summary.clear();
            withoutRoot.clear();
            return List.of();
        }
        return files;
    }

    /** @return what the last {@link #generate()} wrote and did not write, and why (one line each) */
    public List<String> summary() {
        return List.copyOf(summary);
    }

    /** @return the names of the own atom types that got no behaviour class because no root compound instantiates them */
    public List<String> atomsWithoutRoot() {
        return List.copyOf(withoutRoot);
    }

    private void summariseBus(BusPlan plan, SystemModel system, List<JavaFile> eventFiles) {
        String root = system.rootPackage().name() + "." + system.root().name();
        for (BipPackage pkg : workspace.ownPackages()) {
            for (AtomType atom : pkg.atomTypes()) {
                List<String> paths = plan.instances(atom).stream().map(a -> a.path()).toList();
                if (paths.isEmpty()) {
                    withoutRoot.add(atom.name());
                    summary.add("no behaviour class for " + atom.name() + ": root compound " + root
                            + " does not instantiate it");
                } else {
                    summary.add(atom.name() + ": " + JavaNames.javaPackage(pkg) + "."
                            + JavaNames.behaviourClass(JavaNames.type(atom.name())) + " (smart behaviour hosting " + String.join(", ", paths) + " of " + root
                            + ", one copy per group)");
                }
            }
        }
        if (workspace.isOwn(system.rootPackage().name())) {
            summary.add(eventFiles.size() + " event type(s) of " + root + " in Java package "
                    + JavaNames.javaPackage(system.rootPackage()));
        } else {
            summary.add("no event types: they belong to the root compound's package " + system.rootPackage().name()
                    + ", which is used here, not given; they are written where its file is given (the behaviours "
                    + "of this run need them on their class path)");
        }
    }

    private List<JavaFile> busFiles(BusPlan plan, SystemModel system, Map<AtomType, AtomNames> names, Diagnostics bus) {
        List<JavaFile> files = new ArrayList<>();
        for (BipPackage pkg : workspace.ownPackages()) {
            pkg.atomTypes().forEach(plan::ports);
        }
        if (bus.hasErrors()) {
            return files;
        }
        String eventsPackage = JavaNames.javaPackage(system.rootPackage());
        EventsWriter events = new EventsWriter(plan, eventsPackage);
        List<JavaFile> eventFiles = workspace.isOwn(system.rootPackage().name()) ? events.write(bus) : List.of();
        files.addAll(eventFiles);
        for (BipPackage pkg : workspace.ownPackages()) {
            for (AtomType atom : pkg.atomTypes()) {
                if (plan.instances(atom).isEmpty()) {
                    continue;
                }
                AtomNames n = names.get(atom);
                String source = new BehaviourWriter(plan, atom, n, events, bus).write();
                files.add(new JavaFile(n.javaPackage(), n.behaviour(), source));
            }
        }
        if (!bus.hasErrors()) {
            summariseBus(plan, system, eventFiles);
        }
        return files;
    }
}
