package eu.brain.iot.bip.check;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

import eu.brain.iot.bip.model.Annotation;
import eu.brain.iot.bip.model.AtomType;
import eu.brain.iot.bip.model.BipPackage;
import eu.brain.iot.bip.model.CompoundType;
import eu.brain.iot.bip.model.ConnectorType;
import eu.brain.iot.bip.model.ConstDecl;
import eu.brain.iot.bip.model.Decl;
import eu.brain.iot.bip.model.ExternFunction;
import eu.brain.iot.bip.model.ExternOperator;
import eu.brain.iot.bip.model.ExternType;
import eu.brain.iot.bip.model.PortType;

/**
 * What a package sees: its own declarations, then those of the packages it {@code use}s (unqualified), and any
 * package's declarations by qualified name {@code Pkg.Name}. Constants of used packages are visible too (an
 * extension: BIP2 keeps constants package-private; the behaviours share theirs through one package).
 */
public final class PackageScope {

    private final Workspace workspace;
    private final BipPackage pkg;

    public PackageScope(Workspace workspace, BipPackage pkg) {
        this.workspace = workspace;
        this.pkg = pkg;
    }

    public BipPackage pkg() {
        return pkg;
    }

    public Workspace workspace() {
        return workspace;
    }

    /** @return the package that declares {@code decl} (by identity), or this one */
    public BipPackage owner(Decl decl) {
        for (BipPackage p : workspace.packages()) {
            for (Decl d : p.decls()) {
                if (d == decl) {
                    return p;
                }
            }
        }
        return pkg;
    }

    private List<BipPackage> visible() {
        List<BipPackage> list = new ArrayList<>();
        list.add(pkg);
        for (BipPackage.Use use : pkg.uses()) {
            workspace.get(use.packageName()).ifPresent(list::add);
        }
        return list;
    }

    public <T extends Decl> Optional<T> find(Class<T> kind, String name) {
        int dot = name.lastIndexOf('.');
        if (dot > 0) {
            Optional<BipPackage> target = workspace.get(name.substring(0, dot));
            String simple = name.substring(dot + 1);
            return target.flatMap(p -> p.decls(kind).filter(d -> d.name().equals(simple)).findFirst());
        }
        for (BipPackage p : visible()) {
            Optional<T> found = p.decls(kind).filter(d -> d.name().equals(name)).findFirst();
            if (found.isPresent()) {
                return found;
            }
        }
        return Optional.empty();
    }

    public Optional<PortType> portType(String name) {
        return find(PortType.class, name);
    }

    public Optional<AtomType> atomType(String name) {
        return find(AtomType.class, name);
    }

    public Optional<CompoundType> compoundType(String name) {
        return find(CompoundType.class, name);
    }

    public Optional<ConnectorType> connectorType(String name) {
        return find(ConnectorType.class, name);
    }

    public Optional<ConstDecl> constant(String name) {
        return find(ConstDecl.class, name);
    }

    public Optional<ExternType> externType(String name) {
        return find(ExternType.class, name);
    }

    /** @return every extern function named {@code name} visible here (overloads) */
    public List<ExternFunction> functions(String name) {
        List<ExternFunction> list = new ArrayList<>();
        for (BipPackage p : visible()) {
            p.decls(ExternFunction.class).filter(f -> f.name().equals(name)).forEach(list::add);
        }
        return list;
    }

    public List<ExternOperator> operators(String symbol) {
        List<ExternOperator> list = new ArrayList<>();
        for (BipPackage p : visible()) {
            p.decls(ExternOperator.class).filter(f -> f.operator().equals(symbol)).forEach(list::add);
        }
        return list;
    }

    /** @return whether {@code qualifier} may prefix an extern call: a {@code @java(import=...)} name or a package */
    public boolean knownQualifier(String qualifier) {
        for (BipPackage p : visible()) {
            for (Annotation a : p.annotations()) {
                if (a.name().equals("java") && a.value("import").map(qualifier::equals).orElse(false)) {
                    return true;
                }
            }
        }
        return workspace.get(qualifier).isPresent();
    }

    /** Resolves a written type name; unknown names give null. */
    public Type resolveType(String name) {
        Type t = Type.nativeType(name);
        if (t != null) {
            return t;
        }
        return externType(name).map(x -> Type.extern(x.name())).orElse(null);
    }

    /** @return whether a value of type {@code from} may be stored where {@code to} is expected */
    public boolean assignable(Type to, Type from) {
        if (to.isError() || from.isError()) {
            return true;
        }
        if (to.equals(from)) {
            return true;
        }
        if (to.kind() == Type.Kind.FLOAT && from.kind() == Type.Kind.INT) {
            return true;
        }
        if (to.kind() == Type.Kind.EXTERN && from.kind() == Type.Kind.EXTERN) {
            return refines(from.externName(), to.externName(), 0);
        }
        return false;
    }

    private boolean refines(String sub, String sup, int depth) {
        if (sub.equals(sup)) {
            return true;
        }
        if (depth > 20) {
            return false;
        }
        return externType(sub).map(t -> t.refines().stream().anyMatch(r -> refines(r, sup, depth + 1))).orElse(false);
    }
}
