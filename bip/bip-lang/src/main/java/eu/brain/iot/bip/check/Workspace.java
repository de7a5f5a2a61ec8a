package eu.brain.iot.bip.check;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

import eu.brain.iot.bip.diag.Diagnostics;
import eu.brain.iot.bip.model.BipPackage;
import eu.brain.iot.bip.model.Pos;
import eu.brain.iot.bip.parser.Parser;

/**
 * The packages of one run: the files named by the user (its "own" packages) and the packages they {@code use},
 * found as {@code <Package>.bip} (or {@code <last.segment>.bip}) in the model path, like {@code bipc -I}.
 * Owned by the thread that runs the tool.
 */
public final class Workspace {

    private final Map<String, BipPackage> packages = new LinkedHashMap<>();
    private final List<String> own = new ArrayList<>();
    private final List<Path> modelPath;
    private final Diagnostics diagnostics;
    private final java.util.Set<String> missing = new java.util.LinkedHashSet<>();

    public Workspace(List<Path> modelPath, Diagnostics diagnostics) {
        this.modelPath = List.copyOf(modelPath);
        this.diagnostics = diagnostics;
    }

    /** Parses a file given by the user; its package counts as one of the run's own. */
    public Optional<BipPackage> addFile(Path file) {
        String text;
        try {
            text = Files.readString(file, StandardCharsets.UTF_8);
        } catch (IOException | RuntimeException e) {
            diagnostics.error(new Pos(file.toString(), 1, 1), "cannot read the file: " + e.getMessage());
            return Optional.empty();
        }
        return addSource(file.toString(), text);
    }

    /** Parses source text held in memory (tests, fuzzing); its package counts as one of the run's own. */
    public Optional<BipPackage> addSource(String fileName, String text) {
        BipPackage pkg = Parser.parse(fileName, text, diagnostics);
        if (pkg == null) {
            return Optional.empty();
        }
        if (packages.containsKey(pkg.name())) {
            diagnostics.error(pkg.pos(), "package " + pkg.name() + " is defined twice (also in "
                    + packages.get(pkg.name()).pos().file() + ")");
            return Optional.empty();
        }
        packages.put(pkg.name(), pkg);
        own.add(pkg.name());
        return Optional.of(pkg);
    }

    /** Adds an already parsed package as one of the run's own. */
    public void addPackage(BipPackage pkg) {
        packages.put(pkg.name(), pkg);
        own.add(pkg.name());
    }

    private final List<BipPackage.Use> required = new ArrayList<>();

    /** Asks for a package from the model path as if some file used it (e.g. the package of a named root). */
    public void require(String packageName) {
        required.add(new BipPackage.Use(new Pos("<root compound>", 1, 1), packageName));
    }

    /** Loads every package named by a {@code use} (or required), transitively, from the model path. */
    public void resolveUses() {
        List<BipPackage> pending = new ArrayList<>(packages.values());
        pending.add(new BipPackage(Pos.NONE, List.of(), "<required>", required, List.of()));
        while (!pending.isEmpty()) {
            BipPackage pkg = pending.remove(0);
            for (BipPackage.Use use : pkg.uses()) {
                if (packages.containsKey(use.packageName())) {
                    continue;
                }
                Optional<Path> file = find(use.packageName());
                if (file.isEmpty()) {
                    // reported once, at its first use; what follows from it is hidden (see ModelSet.check)
                    if (missing.add(use.packageName())) {
                        String last = use.packageName().substring(use.packageName().lastIndexOf('.') + 1);
                        diagnostics.error(use.pos(), "package " + use.packageName() + " not found: add -I <folder "
                                + "holding " + last + ".bip> (Maven: a <modelPath> entry), or name its file; the "
                                + "model path is " + modelPath);
                    }
                    continue;
                }
                try {
                    String text = Files.readString(file.get(), StandardCharsets.UTF_8);
                    BipPackage used = Parser.parse(file.get().toString(), text, diagnostics);
                    if (used != null) {
                        if (!used.name().equals(use.packageName())) {
                            diagnostics.error(used.pos(), "file " + file.get() + " holds package " + used.name()
                                    + ", but is used as " + use.packageName());
                        }
                        packages.putIfAbsent(use.packageName(), used);
                        pending.add(used);
                    }
                } catch (IOException e) {
                    diagnostics.error(use.pos(), "cannot read " + file.get() + ": " + e.getMessage());
                }
            }
        }
    }

    private Optional<Path> find(String packageName) {
        String last = packageName.substring(packageName.lastIndexOf('.') + 1);
        for (Path dir : modelPath) {
            for (String candidate : List.of(packageName + ".bip", last + ".bip",
                    packageName.replace('.', '/') + ".bip")) {
                Path file = dir.resolve(candidate);
                if (Files.isRegularFile(file)) {
                    return Optional.of(file);
                }
            }
        }
        return Optional.empty();
    }

    /** @return the packages some {@code use} names that are in no file given or found, in order of first use */
    public java.util.Set<String> missingPackages() {
        return java.util.Collections.unmodifiableSet(missing);
    }

    /** @return the loaded packages that use a missing package, directly or through other loaded packages */
    public java.util.Set<String> packagesMissingUses() {
        java.util.Set<String> affected = new java.util.LinkedHashSet<>();
        boolean grew = !missing.isEmpty();
        while (grew) {
            grew = false;
            for (BipPackage p : packages.values()) {
                if (!affected.contains(p.name()) && p.uses().stream()
                        .anyMatch(u -> missing.contains(u.packageName()) || affected.contains(u.packageName()))) {
                    grew = affected.add(p.name());
                }
            }
        }
        return affected;
    }

    public Optional<BipPackage> get(String name) {
        return Optional.ofNullable(packages.get(name));
    }

    public List<BipPackage> packages() {
        return List.copyOf(packages.values());
    }

    /** @return the packages given by the user (not those found through {@code use}) */
    public List<BipPackage> ownPackages() {
        return own.stream().map(packages::get).toList();
    }

    public boolean isOwn(String packageName) {
        return own.contains(packageName);
    }

    public Diagnostics diagnostics() {
        return diagnostics;
    }
}
