package eu.brain.iot.bip.system;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

import eu.brain.iot.bip.check.ConstantFolder;
import eu.brain.iot.bip.check.PackageScope;
import eu.brain.iot.bip.check.Workspace;
import eu.brain.iot.bip.diag.Diagnostics;
import eu.brain.iot.bip.check.Values;
import eu.brain.iot.bip.model.AtomType;
import eu.brain.iot.bip.model.BipPackage;
import eu.brain.iot.bip.model.CompoundType;
import eu.brain.iot.bip.model.ConnectorType;
import eu.brain.iot.bip.model.Expr;
import eu.brain.iot.bip.model.Param;
import eu.brain.iot.bip.model.Pos;

/**
 * A root compound flattened into atom instances and connector instances between their ports, with instance paths
 * such as {@code Robot1} or {@code rcvrs.c1}. Ports exported by the root, and exported atom ports no connector
 * binds, are the system's external ports. Built from a checked workspace.
 */
public final class SystemModel {

    /** An atom instance: its path, type, the package scope of its type, and its parameter values. */
    public record AtomInstance(String path, AtomType type, PackageScope scope, List<Object> args) {
    }

    /** A connector instance; {@code endpoints.get(i)} is bound to the type's port parameter i. */
    public record ConnectorInstance(String path, ConnectorType type, PackageScope scope, List<Endpoint> endpoints,
            Pos pos) {
    }

    /** An atom port, or (when {@code atom} is null) the exported port of connector instance {@code connector}. */
    public record Endpoint(String atom, String port, String connector) {
    }

    private final CompoundType root;
    private final BipPackage rootPackage;
    private final List<AtomInstance> atoms = new ArrayList<>();
    private final List<ConnectorInstance> connectors = new ArrayList<>();
    private final Set<Endpoint> rootExports = new LinkedHashSet<>();

    private SystemModel(CompoundType root, BipPackage rootPackage) {
        this.root = root;
        this.rootPackage = rootPackage;
    }

    public CompoundType root() {
        return root;
    }

    public BipPackage rootPackage() {
        return rootPackage;
    }

    public List<AtomInstance> atoms() {
        return atoms;
    }

    public List<ConnectorInstance> connectors() {
        return connectors;
    }

    public Optional<AtomInstance> atom(String path) {
        return atoms.stream().filter(a -> a.path().equals(path)).findFirst();
    }

    /** @return the connectors that bind this atom port, in declaration order */
    public List<ConnectorInstance> connectorsOf(String atomPath, String port) {
        return connectors.stream().filter(c -> c.endpoints().contains(new Endpoint(atomPath, port, null))).toList();
    }

    /** @return whether the port is exported by the root compound (to the environment) */
    public boolean exportedByRoot(String atomPath, String port) {
        return rootExports.contains(new Endpoint(atomPath, port, null));
    }

    /**
     * Picks the root compound: the one named (simple or qualified name), else the only compound type, else the last
     * compound type of the user's last package that has one. Reports an error when a named one does not exist.
     */
    public static Optional<SystemModel> build(Workspace ws, String rootName, Diagnostics diagnostics) {
        CompoundType root = null;
        BipPackage rootPkg = null;
        for (BipPackage p : ws.packages()) {
            for (CompoundType c : p.compoundTypes()) {
                boolean named = rootName != null && (c.name().equals(rootName) || (p.name() + "." + c.name()).equals(rootName));
                if (named || (rootName == null && ws.isOwn(p.name()))) {
                    root = c;
                    rootPkg = p;
                }
            }
        }
        if (root == null && rootName == null) {
            for (BipPackage p : ws.packages()) {
                for (CompoundType c : p.compoundTypes()) {
                    root = c;
                    rootPkg = p;
                }
            }
        }
        if (root == null) {
            if (rootName != null) {
                diagnostics.error(new Pos("<command line>", 1, 1), "root compound type " + rootName + " not found");
            }
            return Optional.empty();
        }
        SystemModel model = new SystemModel(root, rootPkg);
        PackageScope scope = new PackageScope(ws, rootPkg);
        Map<String, Endpoint> exports = model.flatten(scope, root, "", Map.of(), 0);
        model.rootExports.addAll(exports.values());
        return Optional.of(model);
    }

    /** Flattens {@code c}; @return its exported ports, by export name, resolved to atom endpoints */
    private Map<String, Endpoint> flatten(PackageScope scope, CompoundType c, String prefix, Map<String, Object> params,
            int depth) {
        Map<String, Map<String, Endpoint>> innerExports = new HashMap<>();
        if (depth > 32) {
            return Map.of();
        }
        for (CompoundType.Component k : c.components()) {
            List<Object> args = new ArrayList<>();
            for (Expr a : k.args()) {
                args.add(value(a, scope, params));
            }
            Optional<AtomType> atom = scope.atomType(k.type());
            if (atom.isPresent()) {
                PackageScope atomScope = new PackageScope(scope.workspace(), scope.owner(atom.get()));
                atoms.add(new AtomInstance(prefix + k.name(), atom.get(), atomScope, args));
                continue;
            }
            Optional<CompoundType> inner = scope.compoundType(k.type());
            if (inner.isPresent()) {
                Map<String, Object> innerParams = new HashMap<>();
                for (int i = 0; i < inner.get().params().size() && i < args.size(); i++) {
                    Param p = inner.get().params().get(i);
                    innerParams.put(p.name(), args.get(i));
                }
                PackageScope innerScope = new PackageScope(scope.workspace(), scope.owner(inner.get()));
                innerExports.put(k.name(), flatten(innerScope, inner.get(), prefix + k.name() + ".", innerParams,
                        depth + 1));
            }
        }
        for (CompoundType.Connector k : c.connectors()) {
            Optional<ConnectorType> type = scope.connectorType(k.type());
            if (type.isEmpty()) {
                continue;
            }
            List<Endpoint> endpoints = new ArrayList<>();
            for (CompoundType.PortRef r : k.ports()) {
                endpoints.add(resolve(c, prefix, r, innerExports));
            }
            PackageScope typeScope = new PackageScope(scope.workspace(), scope.owner(type.get()));
            connectors.add(new ConnectorInstance(prefix + k.name(), type.get(), typeScope, endpoints, k.pos()));
        }
        Map<String, Endpoint> exports = new HashMap<>();
        for (CompoundType.PortExport e : c.portExports()) {
            if (!e.ports().isEmpty()) {
                exports.put(e.name(), resolve(c, prefix, e.ports().get(0), innerExports));
            }
        }
        return exports;
    }

    private static Endpoint resolve(CompoundType c, String prefix, CompoundType.PortRef r,
            Map<String, Map<String, Endpoint>> innerExports) {
        Map<String, Endpoint> inner = innerExports.get(r.component());
        if (inner != null) {
            Endpoint e = inner.get(r.port());
            return e != null ? e : new Endpoint(prefix + r.component(), r.port(), null);
        }
        if (c.connector(r.component()).isPresent()) {
            return new Endpoint(null, r.port(), prefix + r.component());
        }
        return new Endpoint(prefix + r.component(), r.port(), null);
    }

    private static Object value(Expr e, PackageScope scope, Map<String, Object> params) {
        if (e instanceof Expr.Var v && v.qualifier() == null && params.containsKey(v.name())) {
            return params.get(v.name());
        }
        if (e instanceof Expr.Unary u && u.op() == Expr.UnaryOp.NEG) {
            Object inner = value(u.operand(), scope, params);
            return inner == null ? null : Values.unary(u.op(), inner);
        }
        return ConstantFolder.fold(e, scope);
    }
}
