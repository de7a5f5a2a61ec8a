package eu.brain.iot.bip.parser;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;

import org.junit.jupiter.api.Test;

import eu.brain.iot.bip.diag.Diagnostic;
import eu.brain.iot.bip.diag.Diagnostics;
import eu.brain.iot.bip.model.BipPackage;

/** Syntax errors: where, what was found, what was expected; every problem of a file in one run. */
class DiagnosticsTest {

    private static List<String> errors(String text) {
        Diagnostics d = new Diagnostics();
        Parser.parse("m.bip", text, d);
        return d.errors().stream().map(Diagnostic::toString).toList();
    }

    @Test
    void namesPositionFoundTextAndExpectation() {
        assertThat(errors("package P\n  atom type A()\n    place S\n    initial to S\n    on p from S { }\n  end\nend\n"))
                .containsExactly("m.bip:5:17: error: expected 'to' in the transition on p, found '{'");
    }

    @Test
    void reportsEveryProblemOfAFileInOneRun() {
        String text = """
                package P
                  port type T(int x
                  atom type A()
                    data int 5
                    place S
                    initial to S
                    on p from S to S provided (x > ) do { x = 1; }
                  end
                  compound type C()
                    component A a(
                  end
                end
                """;
        List<String> errors = errors(text);
        assertThat(errors).hasSize(4);
        assertThat(errors.get(0)).startsWith("m.bip:3:3: error: expected ')' to close the parameters of port type T");
        assertThat(errors.get(1)).isEqualTo("m.bip:4:14: error: expected a data name after type int, found '5'");
        assertThat(errors.get(2)).startsWith("m.bip:7:36: error: expected an expression").contains("found ')'");
        assertThat(errors.get(3)).startsWith("m.bip:11:3: error: expected an expression");
    }

    @Test
    void keepsWhatItCouldReadAroundErrors() {
        Diagnostics d = new Diagnostics();
        BipPackage pkg = Parser.parse("m.bip", """
                package P
                  port type T()
                  atom type A()
                    export port T p()
                    place S, S2
                    initial to S
                    on p from S to S2 provided (1 +) do { }
                    on p from S2 to S
                  end
                  connector type K(T a, T b) define a b end
                end
                """, d);
        assertThat(d.errorCount()).isEqualTo(1);
        assertThat(pkg.atomTypes()).hasSize(1);
        assertThat(pkg.atomTypes().get(0).transitions()).hasSize(1);
        assertThat(pkg.connectorTypes()).hasSize(1);
    }

    @Test
    void lexicalProblemsAreReportedAndSkipped() {
        assertThat(errors("package P # \n const data string s = \"open\n end"))
                .containsExactly("m.bip:1:11: error: unexpected character '#': not part of the BIP language",
                        "m.bip:2:24: error: string is not closed on its line: add '\"'");
        assertThat(errors("package P /* never closed")).first().asString()
                .isEqualTo("m.bip:1:11: error: comment '/*' is never closed: add '*/'");
    }

    @Test
    void missingPackageAndEnd() {
        assertThat(errors("atom type A() end")).first().asString()
                .isEqualTo("m.bip:1:1: error: expected 'package <name>' at the start of the file, found 'atom'");
        assertThat(errors("package P\n port type T()\n")).containsExactly(
                "m.bip:3:1: error: expected 'end' to close package P, found end of file");
    }

    @Test
    void deepNestingIsAnErrorNotAStackOverflow() {
        String deep = "(".repeat(5000) + "1" + ")".repeat(5000);
        List<String> errors = errors("package P const data int x = " + deep + " end");
        assertThat(errors).isNotEmpty();
        assertThat(errors.get(0)).contains("nesting deeper than");
    }

    @Test
    void singleEqualsInAGuardIsReadAsEqualityWithAWarning() {
        Diagnostics d = new Diagnostics();
        Parser.parse("m.bip", "package P const data bool b = 1 = 1 end", d);
        assertThat(d.errors()).isEmpty();
        assertThat(d.all()).singleElement().asString()
                .isEqualTo("m.bip:1:33: warning: '=' inside an expression is read as '=='; write '==' to compare");
    }

    @Test
    void laterBip2ConstructsReportWhatIsMissing() {
        assertThat(errors("""
                package P
                  port type T(const int v)
                  atom type A(const int id)
                    data int x
                    extern port T p(x) as 5
                    extern port T q(x) as "q" forget
                    place S
                    initial to S
                    on p from S to S resume
                    invariant i at provided (x > 0)
                    invariant j x > 0
                  end
                end
                """)).containsExactly(
                "m.bip:5:27: error: expected a string after 'as' in extern port p (the event's name, in quotes), "
                        + "found '5'",
                "m.bip:6:31: error: expected an atom item ('data', 'port', 'extern port', 'place', 'initial', 'on', "
                        + "'internal', 'priority', 'clock', 'invariant' or 'end'), found 'forget'",
                "m.bip:10:20: error: expected a place name of invariant i, found 'provided'",
                "m.bip:11:17: error: expected 'provided' in invariant j (write 'invariant j [at P1, P2] provided "
                        + "(condition)'), found 'x'");
    }

    @Test
    void aBip1ModelIsNamedAsSuch() {
        assertThat(errors("model M\n  port type P()\nend\n")).first().asString().contains("found 'model' (a BIP1 model");
    }
}
