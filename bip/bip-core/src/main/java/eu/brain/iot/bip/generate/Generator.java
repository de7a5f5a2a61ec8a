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
                AtomNames n = new AtomNames(javaPackage, base, base + "Externs", !calls.isEmpty(), base + "Behaviour");
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
            }
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
            }
        }
        return diagnostics.hasErrors() ? List.of() : files;
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
        if (workspace.isOwn(system.rootPackage().name())) {
            files.addAll(events.write(bus));
        }
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
        return files;
    }
}
