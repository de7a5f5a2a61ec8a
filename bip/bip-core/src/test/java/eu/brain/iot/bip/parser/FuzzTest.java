package eu.brain.iot.bip.parser;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;

import eu.brain.iot.bip.Models;
import eu.brain.iot.bip.SyntheticModel;
import eu.brain.iot.bip.Toolchain;
import eu.brain.iot.bip.check.Workspace;
import eu.brain.iot.bip.diag.Diagnostics;

/**
 * 10,000 mutated models (tokens and characters deleted, duplicated, swapped or replaced) never crash the tool: it
 * answers with diagnostics only, and generates Java from those that still check cleanly. In memory, fast.
 */
class FuzzTest {

    private static final int MODELS = 10_000;
    private static final String[] INSERTS = {"(", ")", "{", "}", "'", ";", ",", ".", "end", "on", "from", "to",
            "provided", "do", "if", "then", "else", "fi", "define", "export", "port", "data", "atom type",
            "connector type", "compound type", "component", "connector", "priority", "*:*", "<", "=", "==", "&&",
            "\"", "/*", "//", "@java(", "0x", "1e", "9999999999999", "x", "p1", "START", "int", "float", "string"};

    @Test
    void mutatedModelsNeverCrashTheTool() {
        List<String> seeds = new ArrayList<>();
        for (String name : List.of("package", "atom", "connector", "compound", "expressions")) {
            seeds.add(Models.resource("golden/" + name + ".bip"));
        }
        seeds.add(SyntheticModel.of(80, 11));
        seeds.add(Models.resource("listings/listing7.bip"));
        Random random = new Random(20_240_601);
        int clean = 0;
        for (int i = 0; i < MODELS; i++) {
            String model = mutate(seeds.get(random.nextInt(seeds.size())), random);
            try {
                Workspace ws = new Workspace(List.of(), new Diagnostics());
                ws.addSource("fuzz" + i + ".bip", model);
                ws.resolveUses();
                Toolchain tool = Toolchain.of(ws);
                if (tool.check() && i % 10 == 0) {
                    tool.generateInMemory(null);
                    clean++;
                }
                tool.diagnostics().all().forEach(d -> assertThat(d.pos()).isNotNull());
            } catch (RuntimeException | StackOverflowError e) {
                throw new AssertionError("the tool crashed on mutated model " + i + ":\n" + model, e);
            }
        }
        assertThat(clean).as("some mutants still check and generate").isGreaterThan(0);
    }

    private static String mutate(String seed, Random random) {
        StringBuilder s = new StringBuilder(seed);
        int mutations = 1 + random.nextInt(4);
        for (int m = 0; m < mutations && s.length() > 1; m++) {
            int at = random.nextInt(s.length());
            int len = Math.min(s.length() - at, 1 + random.nextInt(12));
            switch (random.nextInt(5)) {
                case 0 -> s.delete(at, at + len);
                case 1 -> s.insert(at, INSERTS[random.nextInt(INSERTS.length)]);
                case 2 -> s.insert(at, s.substring(at, at + len));
                case 3 -> s.setCharAt(at, (char) (32 + random.nextInt(95)));
                default -> {
                    int other = random.nextInt(s.length());
                    char c = s.charAt(at);
                    s.setCharAt(at, s.charAt(other));
                    s.setCharAt(other, c);
                }
            }
        }
        return s.toString();
    }
}
