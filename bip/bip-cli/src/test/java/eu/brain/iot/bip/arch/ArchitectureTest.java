package eu.brain.iot.bip.arch;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;

/**
 * The BIP toolchain's layering, read from the main sources of its modules: each package lives in exactly one module;
 * dependencies between modules point one way (bip-lang, then bip-generator, then bip-smc, then bip-cli: a module
 * refers to packages of the modules before it only); and the references each source file makes to other packages
 * (imports and qualified names, not the names in the code the generator writes) form no cycle. The interpreter
 * builds on the checker, never the reverse.
 */
class ArchitectureTest {

    /** The modules in their order: each may use the ones before it. */
    private static final List<String> MODULES = List.of("bip-lang", "bip-generator", "bip-smc", "bip-cli");
    private static final Path SOURCES = Path.of("src/main/java/eu/brain/iot/bip");
    private static final Pattern REFERENCE = Pattern.compile("eu\\.brain\\.iot\\.bip\\.([a-z][a-z0-9_.]*?)\\.[A-Z]");
    /** Text blocks and string literals: names in them are code the generator writes, not references. */
    private static final Pattern STRINGS = Pattern.compile("\"\"\"[\\s\\S]*?\"\"\"|\"(?:[^\"\\\\\\n]|\\\\.)*\"");

    @Test
    void everyPackageLivesInOneModule() throws IOException {
        Map<String, Set<String>> modulesOf = new TreeMap<>();
        for (String module : MODULES) {
            for (String pkg : graph(module).keySet()) {
                modulesOf.computeIfAbsent(pkg, k -> new TreeSet<>()).add(module);
            }
        }
        assertThat(modulesOf).containsKeys("model", "parser", "check", "interp", "generate", "smc", "smc.runtime",
                "cli");
        assertThat(modulesOf).allSatisfy((pkg, modules) -> assertThat(modules).as(pkg).hasSize(1));
        assertThat(modulesOf).doesNotContainKey("<root>");
    }

    @Test
    void modulesUseOnlyTheModulesBeforeThem() throws IOException {
        Map<String, Integer> layer = new TreeMap<>();
        for (int i = 0; i < MODULES.size(); i++) {
            for (String pkg : graph(MODULES.get(i)).keySet()) {
                layer.put(pkg, i);
            }
        }
        List<String> upward = new ArrayList<>();
        for (int i = 0; i < MODULES.size(); i++) {
            graph(MODULES.get(i)).forEach((from, targets) -> targets.forEach(to -> {
                if (layer.getOrDefault(to, -1) > layer.get(from)) {
                    upward.add(from + " -> " + to);
                }
            }));
        }
        assertThat(upward).as("references to a later module").isEmpty();
    }

    @Test
    void packagesFormNoCycle() throws IOException {
        Map<String, Set<String>> graph = new TreeMap<>();
        for (String module : MODULES) {
            graph.putAll(graph(module));
        }
        assertThat(graph.get("check")).doesNotContain("interp", "system", "generate");
        List<String> cycles = new ArrayList<>();
        for (String start : graph.keySet()) {
            findCycle(graph, start, new ArrayList<>(List.of(start)), cycles);
        }
        assertThat(cycles).as("package cycles").isEmpty();
    }

    private static void findCycle(Map<String, Set<String>> graph, String start, List<String> path, List<String> out) {
        for (String next : graph.getOrDefault(path.get(path.size() - 1), Set.of())) {
            if (next.equals(start)) {
                out.add(String.join(" -> ", path) + " -> " + start);
            } else if (!path.contains(next) && next.compareTo(start) > 0) {
                path.add(next);
                findCycle(graph, start, path, out);
                path.remove(path.size() - 1);
            }
        }
    }

    /** @return per package of the module's main sources, the other packages its files refer to */
    private static Map<String, Set<String>> graph(String module) throws IOException {
        Path root = Path.of("..", module).resolve(SOURCES);
        assertThat(root).as("the sources of " + module).isDirectory();
        Map<String, Set<String>> graph = new TreeMap<>();
        try (Stream<Path> files = Files.walk(root)) {
            for (Path f : files.filter(p -> p.toString().endsWith(".java")).toList()) {
                Path dir = root.relativize(f.getParent());
                String from = dir.toString().isEmpty() ? "<root>" : dir.toString().replace('/', '.');
                Set<String> to = graph.computeIfAbsent(from, k -> new TreeSet<>());
                Matcher m = REFERENCE.matcher(STRINGS.matcher(Files.readString(f)).replaceAll("\"\""));
                while (m.find()) {
                    if (!m.group(1).equals(from)) {
                        to.add(m.group(1));
                    }
                }
            }
        }
        return graph;
    }
}
