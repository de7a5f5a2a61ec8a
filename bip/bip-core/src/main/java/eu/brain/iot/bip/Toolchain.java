package eu.brain.iot.bip;

import java.nio.file.Path;
import java.util.List;

import eu.brain.iot.bip.check.Checker;
import eu.brain.iot.bip.check.Workspace;
import eu.brain.iot.bip.diag.Diagnostics;
import eu.brain.iot.bip.generate.Generator;
import eu.brain.iot.bip.generate.JavaFile;

/**
 * The one entry point the CLI, the Maven plugin and the benchmark share: load files (and what they {@code use}),
 * check them, generate Java.
 */
public final class Toolchain {

    private final Workspace workspace;
    private boolean checked;
    private Generator generator;

    private Toolchain(Workspace workspace) {
        this.workspace = workspace;
    }

    public static Toolchain load(List<Path> files, List<Path> modelPath, Diagnostics diagnostics) {
        return load(files, modelPath, diagnostics, null);
    }

    /**
     * Loads files and what they use; a qualified {@code root} ({@code Package.Compound}) also loads that package
     * from the model path, so a module can generate its behaviours for a system declared elsewhere.
     */
    public static Toolchain load(List<Path> files, List<Path> modelPath, Diagnostics diagnostics, String root) {
        Workspace ws = new Workspace(modelPath, diagnostics);
        files.forEach(ws::addFile);
        if (root != null && root.lastIndexOf('.') > 0) {
            ws.require(root.substring(0, root.lastIndexOf('.')));
        }
        ws.resolveUses();
        return new Toolchain(ws);
    }

    public static Toolchain of(Workspace workspace) {
        return new Toolchain(workspace);
    }

    public Workspace workspace() {
        return workspace;
    }

    public Diagnostics diagnostics() {
        return workspace.diagnostics();
    }

    /** Checks every loaded package; @return whether there were no errors */
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
        java.util.Set<String> affected = workspace.packagesMissingUses();
        if (affected.isEmpty()) {
            return;
        }
        java.util.Set<String> files = new java.util.HashSet<>();
        for (String name : affected) {
            workspace.get(name).ifPresent(p -> files.add(p.pos().file()));
        }
        diagnostics().hideConsequences(d -> files.contains(d.pos().file()) && d.message().startsWith("unknown "));
    }

    /** Checks, then generates the Java for the own packages in memory (nothing when there are errors). */
    public List<JavaFile> generateInMemory(String root) {
        return generateInMemory(root, false);
    }

    /**
     * @param strictBus whether a system that cannot be realised on the event bus is an error (the Maven plugin) or
     *        warnings with only the atom classes generated (the command line's default)
     */
    public List<JavaFile> generateInMemory(String root, boolean strictBus) {
        if (!check()) {
            return List.of();
        }
        generator = new Generator(workspace, root, strictBus);
        return generator.generate();
    }

    /** @return what the last generation wrote and did not write, and why (one line each; empty before or on errors) */
    public List<String> summary() {
        return generator == null ? List.of() : generator.summary();
    }

    /** @return the own atom types the last generation wrote no behaviour for, as no root compound instantiates them */
    public List<String> atomsWithoutRoot() {
        return generator == null ? List.of() : generator.atomsWithoutRoot();
    }

    /** Checks, then writes the Java under {@code output}; @return the number of files written */
    public int generate(Path output, String root) {
        return generate(output, root, false);
    }

    public int generate(Path output, String root, boolean strictBus) {
        List<JavaFile> files = generateInMemory(root, strictBus);
        if (diagnostics().hasErrors()) {
            return 0;
        }
        for (JavaFile f : files) {
            f.writeUnder(output, diagnostics());
        }
        return files.size();
    }
}
