package eu.brain.iot.bip.parser;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;

import eu.brain.iot.bip.Mutants;
import eu.brain.iot.bip.check.ModelSet;
import eu.brain.iot.bip.check.Workspace;
import eu.brain.iot.bip.diag.Diagnostics;

/**
 * 10,000 mutated models (tokens and characters deleted, duplicated, swapped or replaced) never crash the parser or
 * the checker: they answer with diagnostics only, each at a position. In memory, fast. (The generator's own fuzz
 * test generates Java from the mutants that still check.)
 */
class FuzzTest {

    private static final int MODELS = 10_000;

    @Test
    void mutatedModelsNeverCrashTheParserOrTheChecker() {
        List<String> seeds = Mutants.seeds();
        Random random = new Random(20_240_601);
        int clean = 0;
        for (int i = 0; i < MODELS; i++) {
            String model = Mutants.mutate(seeds.get(random.nextInt(seeds.size())), random);
            try {
                Workspace ws = new Workspace(List.of(), new Diagnostics());
                ws.addSource("fuzz" + i + ".bip", model);
                ws.resolveUses();
                ModelSet models = ModelSet.of(ws);
                if (models.check()) {
                    clean++;
                }
                models.diagnostics().all().forEach(d -> assertThat(d.pos()).isNotNull());
            } catch (RuntimeException | StackOverflowError e) {
                throw new AssertionError("the tool crashed on mutated model " + i + ":\n" + model, e);
            }
        }
        assertThat(clean).as("some mutants still check").isGreaterThan(0);
    }
}
