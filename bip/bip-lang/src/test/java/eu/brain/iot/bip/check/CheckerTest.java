package eu.brain.iot.bip.check;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;

import org.junit.jupiter.api.Test;

import eu.brain.iot.bip.Models;
import eu.brain.iot.bip.SyntheticModel;
import eu.brain.iot.bip.diag.Diagnostic;

/** The checker: names resolve, types agree, connectors fit; unreachable places and dead transitions are warned. */
class CheckerTest {

    private static final String HEAD = "package P\n  port type T(int v)\n  port type F(float f)\n  port type E()\n"
            + "  extern function int f(int)\n  const data int K = 3\n";

    private static List<String> problems(String body) {
        ModelSet tool = Models.check("p.bip", HEAD + body + "end\n");
        return tool.diagnostics().sorted().stream().map(Diagnostic::toString).toList();
    }

    @Test
    void warehouseModelsCheckCleanly() {
        ModelSet tool = Models.warehouse();
        assertThat(tool.diagnostics().all()).isEmpty();
    }

    @Test
    void syntheticModelsCheckCleanly() {
        ModelSet tool = Models.check("s.bip", SyntheticModel.of(2000, 7));
        assertThat(tool.diagnostics().errors()).isEmpty();
    }

    @Test
    void unknownNamesInAtoms() {
        assertThat(problems("""
                  atom type A()
                    data int x
                    export port T p(y)
                    port Missing q()
                    place S
                    initial to S do { z = 1; x = g(2); }
                    on p from S to NOWHERE
                    on r from S to S
                  end
                """)).containsExactly(
                "p.bip:9:5: error: port p binds unknown data 'y'",
                "p.bip:10:5: error: unknown port type 'Missing' of port q: declare it with 'port type Missing(...)'",
                "p.bip:10:5: warning: port q of atom type A labels no transition",
                "p.bip:12:23: error: unknown name 'z': not a data, parameter or constant visible here",
                "p.bip:12:34: error: unknown function 'g': declare it with 'extern function'",
                "p.bip:13:5: error: unknown place 'NOWHERE' after 'to' in atom type A; places are [S]",
                "p.bip:14:5: error: transition on unknown port 'r' in atom type A: declare it with 'port <PortType> r()'");
    }

    @Test
    void typesOfGuardsActionsAndCalls() {
        assertThat(problems("""
                  atom type A(int id)
                    data int x
                    data string s
                    data bool b
                    place S
                    initial to S do { x = "text"; s = "n=" + x; b = x; id = 2; K = 4; x = f(1.5); f(x); }
                    internal from S to S provided (x + 1)
                  end
                """)).containsExactly(
                "p.bip:12:27: error: cannot assign a value of type string to x of type int",
                "p.bip:12:53: error: cannot assign a value of type int to b of type bool",
                "p.bip:12:56: error: cannot assign to id: it is a param, which is read-only",
                "p.bip:12:64: error: cannot assign to K: it is a const, which is read-only",
                "p.bip:12:75: error: no declaration of f takes (float); declared: int f(int)",
                "p.bip:13:38: error: the guard after 'provided' must be a bool, but 'x + 1' is of type int");
    }

    @Test
    void unreachablePlacesAndTransitionsThatCannotFire() {
        assertThat(problems("""
                  atom type A()
                    data int x
                    port E go()
                    place S, T, U, V
                    initial to S
                    on go from S to T
                    on go from T to S provided (K > 5)
                    on go from U to V
                  end
                """)).containsExactly(
                "p.bip:10:17: warning: place U of atom type A is unreachable from the initial place",
                "p.bip:10:20: warning: place V of atom type A is unreachable from the initial place",
                "p.bip:13:5: warning: transition on go from T can never fire: its guard is always false",
                "p.bip:14:5: warning: transition on go from U can never fire: place U is unreachable");
    }

    @Test
    void connectorsAndCompounds() {
        assertThat(problems("""
                  connector type C(T a, T b)
                    define a c
                    on a b provided (a.v > b.w)
                  end
                  connector type D(T a, T b)
                    define a' b
                    on b down { b.v = a.v; }
                  end
                  atom type A()
                    data int x
                    data float y
                    export port T p(x)
                    export port F q(y)
                    port T hidden(x)
                    place S
                    initial to S
                    on p from S to S
                    on q from S to S
                    on hidden from S to S
                  end
                  compound type Top()
                    component A a1(), a2(7)
                    component Nope n()
                    connector D d1(a1.p, a2.q)
                    connector D d2(a1.hidden, ghost.p)
                  end
                """)).containsExactly(
                "p.bip:8:5: warning: port b of connector type C is not in its define expression, so it takes part in no interaction",
                "p.bip:8:14: error: define names unknown port 'c' of connector type C; its ports are [a, b]",
                "p.bip:9:5: error: 'on a b' is not an interaction of connector type C; its define allows []",
                "p.bip:9:28: error: unknown name 'b.w': expected port.data, with port one of the connector's ports [a, b]",
                "p.bip:13:5: error: 'on b' is not an interaction of connector type D; its define allows [[a], [a, b]]",
                "p.bip:28:23: error: component a2 gives 1 arguments, but A takes 0 []",
                "p.bip:29:20: error: unknown component type 'Nope' of component n: expected an atom type or a compound type",
                "p.bip:30:26: error: connector d1: a2.q is a port of type F, but parameter b of D needs T",
                "p.bip:31:20: error: port a1.hidden is not exported: write 'export port T hidden(...)' in atom type A",
                "p.bip:31:31: error: unknown component 'ghost' in ghost.p; components are [a1, a2, n]");
    }

    @Test
    void duplicatesAndMissingInitial() {
        assertThat(problems("""
                  atom type A()
                    data int x
                    data int x
                    place S, S
                  end
                  port type T()
                """)).containsExactly(
                "p.bip:7:3: error: atom type A has no initial transition: add 'initial to <PLACE>'",
                "p.bip:9:14: error: name 'x' is declared twice (first at p.bip:8:14)",
                "p.bip:10:14: error: place 'S' is declared twice (first at p.bip:10:11)",
                "p.bip:12:3: error: port type T is already declared as port type at p.bip:2:3");
    }

    @Test
    void laterBip2Constructs() {
        assertThat(problems("""
                  port type R(const int v, int w)
                  const data int Zero = K - 3
                  const data int Bad = K / Zero
                  const data int Loop = Loop + 1
                  atom type A()
                    data int x, y
                    extern port R ev(x, y) as "ev" remember
                    export port R p(x, y)
                    place S, U
                    initial to S do { y = x / Zero; }
                    on ev from S to U resume
                    on p from U to S
                    invariant i1 at S, NOWHERE provided (x >= 0)
                    invariant i2 provided (x + 1)
                  end
                  connector type C(R a, R b)
                    define a b
                    on a b down { b.v = a.v; b.w = a.v; }
                  end
                  compound type D()
                    component A a1(), a2()
                    connector C c(a1.ev, a2.p)
                  end
                """)).containsExactly(
                "p.bip:9:28: error: integer division by zero: the divisor is always 0, so this always fails when it "
                        + "runs",
                "p.bip:10:30: error: the value of constant Loop cannot be computed when the model is compiled: write "
                        + "it with literals, operators and other constants (no function call, no cycle, no integer "
                        + "division by zero)",
                "p.bip:16:31: error: integer division by zero: the divisor is always 0, so this always fails when it "
                        + "runs",
                "p.bip:19:5: error: unknown place 'NOWHERE' after 'at' in atom type A; places are [S, U]",
                "p.bip:20:30: error: the condition of invariant i2 must be a bool, but 'x + 1' is of type int",
                "p.bip:24:19: error: cannot assign to b.v: its port type declares v 'const' (read-only)",
                "p.bip:28:19: error: connector c binds extern port a1.ev, which only events of the environment fire: "
                        + "bind an ordinary port");
    }
}
