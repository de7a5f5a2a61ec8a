package eu.brain.iot.bip.generate;

import static eu.brain.iot.bip.generate.GeneratedWarehouse.call;
import static eu.brain.iot.bip.generate.GeneratedWarehouse.field;
import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.TreeSet;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import eu.brain.iot.bip.interp.SystemRun;
import eu.brain.iot.bip.system.SystemModel;

/**
 * A coordinated connector over any non-empty subset of participants ({@code define p4 (p1' p2' p3')}, the fix of
 * Listing 7's all-robots rendezvous): the generator makes p4 the coordinator, which fires the largest interaction
 * whose offers are in, running the {@code on} clause of exactly that interaction; after every round the generated
 * behaviours (on an in-order bus) and the interpreter ({@link SystemRun}) are in the same places with the same data,
 * and the interaction the generated coordinator fired is one the interpreter offers as a candidate.
 */
class SubsetRendezvousTest {

    static final String MODEL = """
            package Subset
              port type Pos(int position)
              port type Three(int a, int b, int c)
              port type E()
              connector type Collect(Pos p1, Pos p2, Pos p3, Three p4)
                define p4 (p1' p2' p3')
                on p1 p2 p3 p4 down { p4.a = p1.position; p4.b = p2.position; p4.c = p3.position; }
                on p1 p3 p4 provided (p1.position < p3.position)
                  down { p4.a = p1.position; p4.c = p3.position; p1.position = p3.position + 1; }
                on p2 p4 down { p4.b = p2.position * 2; p2.position = 0; }
              end
              atom type Robot(int id)
                data int position
                data int reports = 0
                export port Pos ready(position)
                export port Pos report(position)
                place IDLE, READY
                initial to IDLE do { position = id * 100; }
                on ready from IDLE to READY
                on report from READY to IDLE do { reports = reports + 1; }
              end
              atom type Orch()
                data int a = 0
                data int b = 0
                data int c = 0
                data int rounds = 0
                export port E go()
                export port Three collect(a, b, c)
                place WAIT, READY
                initial to WAIT
                on go from WAIT to READY
                on collect from READY to WAIT do { rounds = rounds + 1; }
              end
              compound type Top()
                component Robot R1(1), R2(2), R3(3)
                component Orch O()
                connector Collect k(R1.report, R2.report, R3.report, O.collect)
              end
            end
            """;

    private static final List<String> ROBOTS = List.of("R1", "R2", "R3");

    private GeneratedWarehouse bus;
    private Object robots;
    private Object orch;
    private SystemRun run;

    @Test
    void generatedCoordinatorAndInterpreterAgreeOnSubsetRendezvous(@TempDir Path dir) throws Exception {
        Toolchain tool = Tools.check("Subset.bip", MODEL);
        assertThat(tool.diagnostics().errors()).isEmpty();
        bus = new GeneratedWarehouse(tool, "Subset.Top", dir);
        robots = bus.start("subset.RobotBehaviour", null, Map.of());
        orch = bus.start("subset.OrchBehaviour", null, Map.of());
        run = new SystemRun(SystemModel.build(tool.workspace(), "Subset.Top", tool.diagnostics()).orElseThrow(),
                (name, types, result, args) -> {
                    throw new AssertionError("no extern function in this model");
                });
        same();

        // R1 and R3 offer before the coordinator is ready: the 3-participant subset {p1, p3, p4} fires, with its clause
        round(Map.of("R1", 10, "R3", 30), "[p1, p3, p4]");
        assertThat(data(orch, "O")).containsEntry("a", 10).containsEntry("c", 30).containsEntry("b", 0);
        assertThat(data(robots, "R1")).containsEntry("position", 31);

        // {p1, p2, p4} has no clause: it synchronises and transfers nothing
        round(Map.of("R1", 5, "R2", 7), "[p1, p2, p4]");
        assertThat(data(orch, "O")).containsEntry("a", 10).containsEntry("b", 0).containsEntry("rounds", 2);

        // a pair with its own clause
        round(Map.of("R2", 8), "[p2, p4]");
        assertThat(data(orch, "O")).containsEntry("b", 16);
        assertThat(data(robots, "R2")).containsEntry("position", 0);

        // everyone: the largest interaction, Listing 7's
        round(Map.of("R1", 1, "R2", 2, "R3", 3), "[p1, p2, p3, p4]");
        assertThat(data(orch, "O")).containsEntry("a", 1).containsEntry("b", 2).containsEntry("c", 3);

        // the guard of {p1, p3, p4} fails: a pair fires instead ({p1, p4} or {p3, p4}, both maximal), the other waits
        round(Map.of("R1", 50, "R3", 40), null);
        List<Object> fired = bus.published("subset.Collect");
        Object last = fired.get(fired.size() - 1);
        assertThat(last.getClass().getField("participants").get(last).toString()).isIn("[p1, p4]", "[p3, p4]");
        assertThat(fired).allSatisfy(e -> assertThat(field(e, "group")).isNull());
    }

    /** Robots get ready (event with a position), then the coordinator; checks the fired interaction and the states. */
    private void round(Map<String, Integer> ready, String expected) throws Exception {
        int before = bus.published("subset.Collect").size();
        for (String r : new TreeSet<>(ready.keySet())) {
            bus.publish("subset.RobotReady", null, "component", r, "position", ready.get(r));
            assertThat(run.fromEnvironment(r, "ready", List.of(ready.get(r)))).isTrue();
        }
        bus.publish("subset.OrchGo", null, "component", "O");
        assertThat(run.fromEnvironment("O", "go", List.of())).isTrue();

        List<Object> fired = bus.published("subset.Collect");
        assertThat(fired).hasSize(before + 1);
        String participants = field(fired.get(before), "participants").toString();
        if (expected != null) {
            assertThat(participants).isEqualTo(expected);
        }
        List<SystemRun.Candidate> candidates = run.candidates();
        SystemRun.Candidate same = candidates.stream()
                .filter(c -> c.ports().stream().map(e -> "p" + (ROBOTS.indexOf(e.atom()) + 1)).toList().toString()
                        .replace("p0", "p4").equals(participants))
                .findFirst().orElseThrow(() -> new AssertionError("the generated coordinator fired " + participants
                        + ", which is not a candidate of the interpreter: " + candidates));
        run.execute(same);
        same();
    }

    /** Every component is in the same places with the same data (atom data) in the generated code and the interpreter. */
    private void same() {
        for (String c : List.of("R1", "R2", "R3", "O")) {
            Object b = c.equals("O") ? orch : robots;
            assertThat(new TreeSet<>((List<?>) call(b, "placesOf", c))).as(c).isEqualTo(run.atom(c).marking());
            Map<String, Object> generated = new TreeMap<>(data(b, c));
            Map<String, Object> interpreted = new TreeMap<>(run.atom(c).values());
            interpreted.keySet().retainAll(generated.keySet()); // the interpreter also lists the atom's parameters
            assertThat(generated).as(c).isEqualTo(interpreted).containsKey(c.equals("O") ? "rounds" : "reports");
        }
    }

    @SuppressWarnings("unchecked")
    private static Map<String, Object> data(Object behaviour, String component) {
        return (Map<String, Object>) call(behaviour, "dataOf", component);
    }
}
