package eu.brain.iot.bip.cli;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.stream.Stream;

import eu.brain.iot.bip.diag.Diagnostics;
import eu.brain.iot.bip.model.BipPackage;
import eu.brain.iot.bip.model.CompoundType;
import eu.brain.iot.bip.parser.Parser;

/**
 * Tells a user who generated an atom type without its system how to get its behaviour class: looks through the
 * model path for compound types that instantiate the atom type and names the {@code --root} and {@code -I} flags
 * that would generate it. Reads the model path's {@code *.bip} files (top level of each folder) and parses them
 * with diagnostics of its own, so a broken file there never adds to the run's problems.
 */
final class RootHint {

    private RootHint() {
    }

    /** @return one line per atom type: the flags that would write its behaviour */
    static List<String> lines(List<String> atomTypes, List<Path> modelPath) {
        List<BipPackage> packages = new ArrayList<>();
        for (Path dir : new LinkedHashSet<>(modelPath)) {
            if (!Files.isDirectory(dir)) {
                continue;
            }
            try (Stream<Path> files = Files.list(dir)) {
                for (Path f : files.filter(p -> p.toString().endsWith(".bip")).sorted().toList()) {
                    BipPackage p = Parser.parse(f.toString(), Files.readString(f, StandardCharsets.UTF_8),
                            new Diagnostics());
                    if (p != null) {
                        packages.add(p);
                    }
                }
            } catch (IOException | RuntimeException unreadable) {
                // a hint only: a folder that cannot be read gives none
            }
        }
        List<String> lines = new ArrayList<>();
        for (String atom : atomTypes) {
            Set<String> roots = new LinkedHashSet<>();
            for (BipPackage p : packages) {
                for (CompoundType c : p.compoundTypes()) {
                    if (c.components().stream().anyMatch(k -> k.type().equals(atom) || k.type().endsWith("." + atom))) {
                        roots.add("--root " + p.name() + "." + c.name() + " (in " + p.pos().file() + ")");
                    }
                }
            }
            lines.add(roots.isEmpty()
                    ? "to generate the behaviour of " + atom + ": give the file of the compound type that instantiates "
                            + "it (or --root Package.Compound with -I for its folder), and -I for every model folder"
                    : "to generate the behaviour of " + atom + ": give " + String.join(" or ", roots)
                            + " and -I for the folder of every package it uses");
        }
        return lines;
    }
}
