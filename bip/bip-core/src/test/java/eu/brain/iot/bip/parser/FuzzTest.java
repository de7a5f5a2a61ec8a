package eu.brain.iot.bip.parser;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;

import eu.brain.iot.bip.Mutants;
import eu.brain.iot.bip.Toolchain;
import eu.brain.iot.bip.check.Workspace;
import eu.brain.iot.bip.diag.Diagnostics;

/**
 * 10,000 mutated models (tokens and characters deleted, duplicated, swapped or replaced) never crash the tool: it
 * answers with diagnostics only, and generates Java from those that still check cleanly. In memory, fast.
 */
class FuzzTest {

    private static final int MODELS = 10_000;

    @Test
    void mutatedModelsNeverCrashTheTool() {
        List<String> seeds = Mutants.seeds();
        Random random = new Random(20_240_601);
        int clean = 0;
        for (int i = 0; i < MODELS; i++) {
            String model = Mutants.mutate(seeds.get(random.nextInt(seeds.size())), random);
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
}
