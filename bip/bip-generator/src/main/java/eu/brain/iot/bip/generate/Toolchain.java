package eu.brain.iot.bip.generate;

import java.nio.file.Path;
import java.util.List;

import eu.brain.iot.bip.check.ModelSet;
import eu.brain.iot.bip.check.Workspace;
import eu.brain.iot.bip.diag.Diagnostics;

/**
 * Load, check, generate Java: the entry point the command line and the Maven plugin share. Loading
 * and checking are the language's ({@link ModelSet}); this adds the generation and what it says it wrote. Not
 * thread-safe: one run owns it.
 */
public final class Toolchain {

    private final ModelSet models;
    private Generator generator;

    private Toolchain(ModelSet models) {
        this.models = models;
    }

    public static Toolchain load(List<Path> files, List<Path> modelPath, Diagnostics diagnostics) {
        return load(files, modelPath, diagnostics, null);
    }

    /** See {@link ModelSet#load(List, List, Diagnostics, String)}. */
    public static Toolchain load(List<Path> files, List<Path> modelPath, Diagnostics diagnostics, String root) {
        return new Toolchain(ModelSet.load(files, modelPath, diagnostics, root));
    }

    public static Toolchain of(ModelSet models) {
        return new Toolchain(models);
    }

    public static Toolchain of(Workspace workspace) {
        return new Toolchain(ModelSet.of(workspace));
    }

    public ModelSet models() {
        return models;
    }

    public Workspace workspace() {
        return models.workspace();
    }

    public Diagnostics diagnostics() {
        return models.diagnostics();
    }

    /** Checks every loaded package (once); @return whether there were no errors */
    public boolean check() {
        return models.check();
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
        generator = new Generator(workspace(), root, strictBus);
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
