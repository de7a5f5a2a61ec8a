package eu.brain.iot.bip.generate;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import eu.brain.iot.bip.diag.Diagnostic;

/**
 * The BRAIN-IoT tools' dialect, as their models use it, checks (with warnings where it is loose) and generates Java
 * that compiles: @java imports, qualified calls (one matching no declaration), strings joined with numbers in
 * connector code, 'up' writing port data, int arguments for double parameters, the paper's 'extern int f ()',
 * only local ports (a robot driven by extern calls), and two instances of one type at both ends of a rendezvous.
 */
class DialectTest {

    @TempDir
    Path out;

    private static final String MODEL = """
            @java(import="Printer",src="org.printer")

            @java(import="Command",src="org.lib.Command")
            package RobotDialect
              extern function print(int, string)
              extern function int getDockingX()
              extern function int sendGoto (double x,double y,double z)
              extern int ready ()
              port type ePort  ()         // silent
              port type Position(int varid, int placeX, int placeY)
              atom type Robot (int id)
                data int locationX
                data int locationY
                data int varid
                data int RESPONSE
                data string TEXT
                export port Position pos (varid, locationX, locationY)
                port ePort p0()
                port ePort p1()
                place STARTR, Ready, Moving
                initial to STARTR do{locationX = Command.getDockingX(); varid =id; TEXT= "**STARTING**";}
                on p0 from STARTR to Ready provided (Command.ready() == 1) do{ RESPONSE = Command.sendGoto(locationX,1,2); }
                on p1 from Ready to Moving provided (!(RESPONSE==1)) do{ TEXT = "moving " + varid; }
                on pos from Moving to STARTR do{}
              end
              connector type robotPosition(Position m, Position s)
                data string txt
                data int id
                define s m
                on s m up {m.placeX =s.placeX ;m.placeY =s.placeY ; id = s.varid; txt ="("+s.varid+")-->"+"("+m.varid+")"; Printer.print(txt,id);}
              end
              compound type sim07()
                component Robot robot (1), other (2)
                connector robotPosition c3(robot.pos, other.pos)
              end
            end
            """;

    @Test
    void dialectModelsCheckAndGenerateCompilableJava() {
        Toolchain tool = Tools.check("RobotDialect.bip", MODEL);
        assertThat(tool.diagnostics().errors()).isEmpty();
        assertThat(tool.diagnostics().all()).extracting(Diagnostic::toString).anySatisfy(w -> assertThat(w)
                .contains("warning: no declaration of print takes (string, int)"));
        List<JavaFile> files = tool.generateInMemory(null);
        assertThat(tool.diagnostics().errors()).isEmpty();
        String externs = files.stream().filter(f -> f.className().equals("RobotExterns")).findFirst().orElseThrow()
                .source();
        assertThat(externs).contains("int sendGoto(double x, double y, double z);", "int ready();",
                "void print(String arg0, int arg1);", "int getDockingX();");
        InMemoryCompiler.compile(files, out);
    }
}
