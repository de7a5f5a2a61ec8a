package eu.brain.iot.bip.interp;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

import org.junit.jupiter.api.Test;

import eu.brain.iot.bip.Models;
import eu.brain.iot.bip.check.ModelSet;
import eu.brain.iot.bip.system.SystemModel;

/** The system interpreter follows the BIP semantics on small closed models (after the BIP2 tutorial). */
class SystemRunTest {

    private static SystemRun run(String model, List<String> printed) {
        ModelSet tool = Models.check("m.bip", model);
        assertThat(tool.diagnostics().errors()).isEmpty();
        SystemModel system = SystemModel.build(tool.workspace(), null, tool.diagnostics()).orElseThrow();
        return new SystemRun(system, (name, types, result, args) -> {
            printed.add(name + java.util.Arrays.toString(args));
            return null;
        });
    }

    @Test
    void rendezvousFiresOnlyWhenEveryPortIsReady() {
        List<String> printed = new ArrayList<>();
        SystemRun run = run("""
                package Hello
                  extern function printf(string, int)
                  port type P()
                  atom type A(int id)
                    export port P p()
                    place START, END
                    initial to START
                    on p from START to END do { printf("hello from", id); }
                  end
                  connector type Three(P p1, P p2, P p3)
                    define p1 p2 p3
                  end
                  compound type C()
                    component A c1(1), c2(2), c3(3)
                    connector Three connect(c1.p, c2.p, c3.p)
                  end
                end
                """, printed);
        assertThat(run.candidates()).extracting(Object::toString).containsExactly("connect: [c1.p, c2.p, c3.p]");
        assertThat(run.step(c -> 0)).contains("connect: [c1.p, c2.p, c3.p]");
        assertThat(printed).containsExactly("printf[hello from, 1]", "printf[hello from, 2]", "printf[hello from, 3]");
        assertThat(run.atoms().values()).allSatisfy(a -> assertThat(a.marking()).containsExactly("END"));
        assertThat(run.step(c -> 0)).isEqualTo(Optional.empty());
    }

    @Test
    void broadcastTakesTheMaximalInteractionOfReadyReceiversAndTransfersData() {
        SystemRun run = run("""
                package Brd
                  port type P(int d)
                  atom type Sender(int id)
                    data int myd
                    export port P p(myd)
                    place START, END
                    initial to START do { myd = id; }
                    on p from START to END
                  end
                  atom type Receiver(int id)
                    data int myd = -1
                    export port P p(myd)
                    place START, END
                    initial to START
                    on p from START to END provided (id == 1 || id == 3)
                  end
                  connector type OneToThree(P s, P r1, P r2, P r3)
                    define s' r1 r2 r3
                    on s r1 r3 down { r1.d = s.d; r3.d = s.d + 1; }
                  end
                  compound type C()
                    component Sender s(7)
                    component Receiver r1(1), r2(2), r3(3)
                    connector OneToThree brd(s.p, r1.p, r2.p, r3.p)
                  end
                end
                """, new ArrayList<>());
        assertThat(run.candidates()).extracting(Object::toString).containsExactly("brd: [s.p, r1.p, r3.p]");
        run.step(c -> 0);
        assertThat(run.atom("r1").get("myd")).isEqualTo(7);
        assertThat(run.atom("r3").get("myd")).isEqualTo(8);
        assertThat(run.atom("r2").get("myd")).isEqualTo(-1);
        assertThat(run.atom("r2").marking()).containsExactly("START");
    }

    @Test
    void internalTransitionsGoFirstAndLocalPortsFireAlone() {
        SystemRun run = run("""
                package Local
                  port type P()
                  atom type A()
                    data int n = 0
                    port P tick()
                    place S, T
                    initial to S
                    internal from S to T provided (n == 0) do { n = 1; }
                    on tick from T to S do { n = n + 10; }
                  end
                  compound type C()
                    component A a()
                  end
                end
                """, new ArrayList<>());
        assertThat(run.step(c -> 0)).contains("internal a");
        assertThat(run.step(c -> 0)).contains("[a.tick]");
        assertThat(run.atom("a").get("n")).isEqualTo(11);
        assertThat(run.atom("a").marking()).containsExactly("S");
    }

    @Test
    void listing7DeliversThePositionsToTheOrchestrator() {
        SystemRun run = run("""
                package Rdv
                  port type Port_Robot_Position(float position)
                  port type Port_Orchestrator(float position1, float position2, float position3)
                  atom type Robot(float start)
                    data float position
                    export port Port_Robot_Position resolveCollision(position)
                    place OBSTACLE, ROBOT
                    initial to OBSTACLE do { position = start; }
                    on resolveCollision from OBSTACLE to ROBOT
                  end
                  atom type Orchestrator()
                    data float position1, position2, position3
                    export port Port_Orchestrator resolveCollision(position1, position2, position3)
                    place START, COLLISION
                    initial to START
                    on resolveCollision from START to COLLISION
                  end
                """ + Models.resource("listings/listing7.bip") + """
                  compound type C()
                    component Robot r1(1.5), r2(2), r3(3)
                    component Orchestrator o()
                    connector connector_resolve_collision c(r1.resolveCollision, r2.resolveCollision,
                        r3.resolveCollision, o.resolveCollision)
                  end
                end
                """, new ArrayList<>());
        run.step(c -> 0);
        assertThat(run.atom("o").values()).containsEntry("position1", 1.5).containsEntry("position2", 2.0)
                .containsEntry("position3", 3.0);
        assertThat(run.atom("o").marking()).containsExactly("COLLISION");
    }

    @Test
    void theEnvironmentFiresTheExportedPortsNoConnectorBinds() {
        SystemRun run = run("""
                package Open
                  port type Status(float position, int detect)
                  port type Go()
                  atom type Robot()
                    data float position
                    data int detect
                    export port Status poll(position, detect)
                    export port Go go()
                    place START, MOVED
                    initial to START
                    on poll from START to MOVED provided (detect == 0)
                    on go from MOVED to START
                  end
                  atom type Peer()
                    export port Go go()
                    place P
                    initial to P
                    on go from P to P
                  end
                  connector type Sync(Go a, Go b)
                    define a b
                  end
                  compound type C()
                    component Robot r()
                    component Peer q()
                    connector Sync s(r.go, q.go)
                  end
                end
                """, new ArrayList<>());
        assertThat(run.environmentPort("r", "poll")).isTrue();
        assertThat(run.environmentPort("r", "go")).as("bound by a connector").isFalse();
        assertThat(run.environmentPort("q", "go")).isFalse();
        assertThat(run.candidates()).as("the SMC never fires the environment's ports").isEmpty();
        assertThat(run.environmentCandidates()).extracting(Object::toString).containsExactly("[r.poll]");
        assertThat(run.fromEnvironment("r", "poll", List.of(2.5, 0))).isTrue();
        assertThat(run.atom("r").marking()).containsExactly("MOVED");
        assertThat(run.atom("r").values()).containsEntry("position", 2.5).containsEntry("detect", 0);
        assertThat(run.environmentCandidates()).isEmpty();
        assertThat(run.fromEnvironment("r", "poll", List.of(3.0, 4))).as("not enabled: no step").isFalse();
        assertThat(run.atom("r").get("position")).isEqualTo(2.5);
        org.assertj.core.api.Assertions.assertThatThrownBy(() -> run.fromEnvironment("r", "go", List.of()))
                .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("r.go is not a port of the "
                        + "environment");
    }

    private static final String SENSORS = """
            package Sensors
              port type Reading(const int value)
              port type Tick()
              atom type Sensor(int limit)
                data int level
                extern port Reading sample(level) as "sample" remember
                extern port Tick reset() as "reset" ignore
                extern port Tick fault() as "fault" error
                port Tick report()
                place IDLE, MEASURED
                initial to IDLE
                on sample from IDLE to MEASURED resume
                on report from MEASURED to IDLE
                on reset from MEASURED to IDLE do { level = 0; }
                on fault from MEASURED to MEASURED
                invariant belowLimit at MEASURED provided (level <= limit)
              end
              compound type Plant()
                component Sensor s(10)
              end
            end
            """;

    @Test
    void externPortsTakeEnvironmentEventsByTheirPolicy() {
        SystemRun run = run(SENSORS, new ArrayList<>());
        assertThat(run.candidates()).as("no event yet: extern ports are no candidates").isEmpty();
        assertThat(run.deliver("s", "sample", List.of(4))).isEqualTo(SystemRun.Delivery.FIRED);
        assertThat(run.atom("s").marking()).containsExactly("MEASURED");
        assertThat(run.atom("s").get("level")).isEqualTo(4);

        assertThat(run.deliver("s", "sample", List.of(7))).isEqualTo(SystemRun.Delivery.REMEMBERED);
        assertThat(run.deliver("s", "fault", List.of())).isEqualTo(SystemRun.Delivery.FIRED);
        assertThat(run.candidates()).extracting(Object::toString).containsExactly("[s.report]");
        run.step(c -> 0);
        assertThat(run.deliver("s", "reset", List.of())).isEqualTo(SystemRun.Delivery.IGNORED);
        assertThat(run.deliver("s", "fault", List.of())).isEqualTo(SystemRun.Delivery.REFUSED);
        assertThat(run.errors()).containsExactly(
                "s.fault: an event arrived when the port could not take it (policy error)");
        assertThat(run.candidates()).as("the remembered sample, now that sample is enabled")
                .extracting(Object::toString).containsExactly("[s.sample]");
        run.step(c -> 0);
        assertThat(run.atom("s").get("level")).isEqualTo(7);
        assertThat(run.candidates()).extracting(Object::toString).containsExactly("[s.report]");
    }

    @Test
    void invariantsAreObservedNotEnforced() {
        SystemRun run = run(SENSORS, new ArrayList<>());
        assertThat(run.violatedInvariants()).isEmpty();
        run.atom("s").set("level", 99);
        assertThat(run.violatedInvariants()).as("at IDLE the invariant does not apply").isEmpty();
        assertThat(run.deliver("s", "sample", List.of(11))).isEqualTo(SystemRun.Delivery.FIRED);
        assertThat(run.violatedInvariants()).containsExactly(java.util.Map.entry("s", List.of("belowLimit")));
        assertThat(run.atom("s").violatedInvariants()).containsExactly("belowLimit");
        assertThat(run.candidates()).as("the run goes on").isNotEmpty();
    }

    @Test
    void externOperatorsCallTheExterns() {
        List<String> calls = new ArrayList<>();
        ModelSet tool = Models.check("v.bip", """
                package Vec
                  extern data type V
                  extern function V unit()
                  extern operator V +(V, V)
                  extern operator V -(V)
                  extern operator bool ==(V, V)
                  port type P()
                  atom type A()
                    data V v
                    data bool same
                    port P p()
                    place S
                    initial to S do { v = unit(); }
                    on p from S to S do { v = v + -v; same = v == unit(); }
                  end
                  compound type C()
                    component A a()
                  end
                end
                """);
        assertThat(tool.diagnostics().errors()).isEmpty();
        SystemModel system = SystemModel.build(tool.workspace(), null, tool.diagnostics()).orElseThrow();
        SystemRun run = new SystemRun(system, (name, types, result, args) -> {
            calls.add(name + types + java.util.Arrays.toString(args));
            return switch (name) {
                case "unit" -> "u";
                case "operatorNeg" -> "-" + args[0];
                case "operatorAdd" -> "(" + args[0] + "+" + args[1] + ")";
                default -> args[0].equals(args[1]);
            };
        });
        run.step(c -> 0);
        assertThat(run.atom("a").get("v")).isEqualTo("(u+-u)");
        assertThat(run.atom("a").get("same")).isEqualTo(false);
        assertThat(calls).containsExactly("unit[][]", "operatorNeg[V][u]", "operatorAdd[V, V][u, -u]", "unit[][]",
                "operatorEq[V, V][(u+-u), u]");
    }
}
