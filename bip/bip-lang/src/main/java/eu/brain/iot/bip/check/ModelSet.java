package eu.brain.iot.bip.check;

import java.nio.file.Path;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

import eu.brain.iot.bip.diag.Diagnostics;

/**
 * The models of one run: the given files, the packages they {@code use} found on the model path, checked once. The
 * entry point the generator, the statistical model checker, the command line and the Maven plugin share to turn
 * files into a checked {@link Workspace}. Not thread-safe: one run owns it.
 */
public final class ModelSet {

    private final Workspace workspace;
    private boolean checked;

    private ModelSet(Workspace workspace) {
        this.workspace = workspace;
    }

    public static ModelSet load(List<Path> files, List<Path> modelPath, Diagnostics diagnostics) {
        return load(files, modelPath, diagnostics, null);
    }

    /**
     * Loads files and what they use; a qualified {@code root} ({@code Package.Compound}) also loads that package
     * from the model path, so a module can generate its behaviours for a system declared elsewhere.
     */
    public static ModelSet load(List<Path> files, List<Path> modelPath, Diagnostics diagnostics, String root) {
        Workspace ws = new Workspace(modelPath, diagnostics);
        files.forEach(ws::addFile);
        if (root != null && root.lastIndexOf('.') > 0) {
            ws.require(root.substring(0, root.lastIndexOf('.')));
        }
        ws.resolveUses();
        return new ModelSet(ws);
    }

    /** A set over a workspace already filled (sources added and uses resolved). */
    public static ModelSet of(Workspace workspace) {
        return new ModelSet(workspace);
    }

    public Workspace workspace() {
        return workspace;
    }

    public Diagnostics diagnostics() {
        return workspace.diagnostics();
    }

    /** Checks every loaded package (the first call only); @return whether there were no errors */
    public boolean check() {
        if (!checked) {
            Checker.check(workspace);
            checked = true;
            hideWhatFollowsFromMissingPackages();
        }
        return !diagnostics().hasErrors();
    }

    /**
     * A package that is not found makes every name it declares unknown in the packages that use it: one error
     * ("package Warehouse not found: add -I ...") says it all, so the unresolved names of those packages are hidden
     * (counted in {@link Diagnostics#hiddenCount()}, still failing the run).
     */
    private void hideWhatFollowsFromMissingPackages() {
        Set<String> affected = workspace.packagesMissingUses();
        if (affected.isEmpty()) {
            return;
        }
        Set<String> files = new HashSet<>();
        for (String name : affected) {
            workspace.get(name).ifPresent(p -> files.add(p.pos().file()));
        }
        diagnostics().hideConsequences(d -> files.contains(d.pos().file()) && d.message().startsWith("unknown "));
    }
}
