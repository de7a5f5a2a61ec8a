package eu.brain.iot.bip.generate;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;

import eu.brain.iot.bip.Mutants;
import eu.brain.iot.bip.check.Workspace;
import eu.brain.iot.bip.diag.Diagnostics;

/**
 * Mutated models that still check (tokens and characters deleted, duplicated, swapped or replaced) never crash the
 * generator: every tenth of 10,000 mutants is checked and, when it checks cleanly, generated in memory.
 */
class GeneratorFuzzTest {

    private static final int MODELS = 10_000;
    private static final int EVERY = 10;

    @Test
    void mutatedModelsThatCheckNeverCrashTheGenerator() {
        List<String> seeds = Mutants.seeds();
        Random random = new Random(20_240_601);
        int generated = 0;
        for (int i = 0; i < MODELS; i++) {
            String model = Mutants.mutate(seeds.get(random.nextInt(seeds.size())), random);
            if (i % EVERY != 0) {
                continue;
            }
            try {
                Workspace ws = new Workspace(List.of(), new Diagnostics());
                ws.addSource("fuzz" + i + ".bip", model);
                ws.resolveUses();
                Toolchain tool = Toolchain.of(ws);
                if (tool.check()) {
                    tool.generateInMemory(null);
                    generated++;
                }
                tool.diagnostics().all().forEach(d -> assertThat(d.pos()).isNotNull());
            } catch (RuntimeException | StackOverflowError e) {
                throw new AssertionError("the generator crashed on mutated model " + i + ":\n" + model, e);
            }
        }
        assertThat(generated).as("some mutants still check and generate").isGreaterThan(0);
    }
}
