package eu.brain.iot.bip.parser;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;

import org.junit.jupiter.api.Test;

import eu.brain.iot.bip.Models;
import eu.brain.iot.bip.check.ModelSet;
import eu.brain.iot.bip.diag.Diagnostic;
import eu.brain.iot.bip.model.AtomType;
import eu.brain.iot.bip.model.BipPackage;
import eu.brain.iot.bip.model.CompoundType;
import eu.brain.iot.bip.model.ConnectorType;
import eu.brain.iot.bip.model.Expr;
import eu.brain.iot.bip.model.Pos;

/**
 * The paper's listings (src/test/resources/listings, line numbers stripped) parse verbatim. They are fragments, so
 * each is placed inside the smallest package that gives it context; Listing 1's two '...' lines (elided text) are
 * left out; Listing 5 and the section 6.2 transition are placed in an atom.
 */
class PaperListingsTest {

    private static final String PORT_TYPES = """
            port type Port()
            port type Port_Silent()
            port type Port_Robot_Position(float position)
            port type Port_Orchestrator(float position1, float position2, float position3)
            """;

    private static ModelSet load(String text) {
        return Models.check("paper.bip", text);
    }

    private static List<String> errors(ModelSet tool) {
        return tool.diagnostics().errors().stream().map(Diagnostic::toString).toList();
    }

    @Test
    void listing1ParsesAndChecks() {
        ModelSet tool = load("package Paper\n" + PORT_TYPES + "extern function initRobot()\n"
                + Models.resource("listings/listing1.bip") + "end\n");
        assertThat(errors(tool)).isEmpty();
        AtomType robot = tool.workspace().get("Paper").orElseThrow().atomTypes().get(0);
        assertThat(robot.transitions().get(0).guard()).isEqualTo(new Expr.Binary(Pos.NONE, Expr.BinaryOp.AND,
                new Expr.Binary(Pos.NONE, Expr.BinaryOp.EQ, new Expr.Var(Pos.NONE, null, "positionX"), new Expr.IntLit(Pos.NONE, 1)),
                new Expr.Binary(Pos.NONE, Expr.BinaryOp.EQ, new Expr.Var(Pos.NONE, null, "positionY"), new Expr.IntLit(Pos.NONE, 6))));
    }

    @Test
    void listing4ParsesAndTheCheckerFindsItsMisnamedDoor() {
        String types = PORT_TYPES + Models.resource("listings/listing6.bip") + Models.resource("listings/listing7.bip")
                + """
                connector type connector_collision_resolved(Port_Robot_Position p1, Port_Robot_Position p2,
                    Port_Robot_Position p3, Port_Orchestrator p4) define p1 p2 p3 p4 end
                atom type Door_behavior() export port Port_Silent openDoor() place S initial to S
                  on openDoor from S to S end
                atom type Robot_behavior(int VID) data float position
                  export port Port_Silent openDoor() export port Port_Robot_Position resolveCollision(position)
                  export port Port_Robot_Position collisionResolved(position) place S initial to S
                  on openDoor from S to S on resolveCollision from S to S on collisionResolved from S to S end
                atom type Orchestrator_behavior() data float a, b, c
                  export port Port_Orchestrator resolveCollision(a, b, c)
                  export port Port_Orchestrator collisionResolved(a, b, c) place S initial to S
                  on resolveCollision from S to S on collisionResolved from S to S end
                """;
        ModelSet tool = load("package Paper\n" + types + Models.resource("listings/listing4.bip") + "end\n");
        BipPackage pkg = tool.workspace().get("Paper").orElseThrow();
        CompoundType compound = pkg.compoundTypes().get(0);
        assertThat(compound.components()).extracting(CompoundType.Component::name)
                .containsExactly("Door", "Robot1", "Robot2", "Robot3", "Orchestrator1");
        assertThat(compound.connectors().get(1).ports()).extracting(Object::toString).containsExactly(
                "Robot1.resolveCollision", "Robot2.resolveCollision", "Robot3.resolveCollision",
                "Orchestrator1.resolveCollision");
        // the listing's connector names DoorInstance, but its door component is called Door
        assertThat(errors(tool)).singleElement().asString().contains("unknown component 'DoorInstance'");
    }

    @Test
    void listing5ParsesInAnAtom() {
        ModelSet tool = load("package Paper\nextern int getPosition ()\natom type R(int VID)\n data int id\n"
                + " data int position\n place START\n" + Models.resource("listings/listing5.bip") + "end\nend\n");
        assertThat(errors(tool)).isEmpty();
        assertThat(tool.workspace().get("Paper").orElseThrow().atomTypes().get(0).initial().action().stmts())
                .hasSize(2);
    }

    @Test
    void listings6And7ParseAndCheck() {
        ModelSet tool = load("package Paper\n" + PORT_TYPES + Models.resource("listings/listing6.bip")
                + Models.resource("listings/listing7.bip") + "end\n");
        assertThat(errors(tool)).isEmpty();
        List<ConnectorType> connectors = tool.workspace().get("Paper").orElseThrow().connectorTypes();
        assertThat(connectors.get(0).define()).isNull();
        assertThat(connectors.get(0).interactions()).hasSize(3);
        assertThat(connectors.get(1).interactions().get(0).down().stmts()).hasSize(3);
    }

    @Test
    void section62FragmentsParse() {
        ModelSet tool = load("package Paper\n" + Models.resource("listings/section62.bip")
                + "const data int inFrontOfCart = 6\nextern function int liftCart()\n"
                + "atom type R()\n data int position\n data int cart\n port Port_Type_No_Param cartDetected()\n"
                + " place OBSTACLE, CART\n initial to OBSTACLE\n" + Models.resource("listings/section62-transition.bip")
                + "end\nend\n");
        assertThat(errors(tool)).isEmpty();
        AtomType r = tool.workspace().get("Paper").orElseThrow().atomTypes().get(0);
        assertThat(r.transitions().get(0).from()).containsExactly("OBSTACLE");
        assertThat(r.transitions().get(0).to()).containsExactly("CART");
    }
}
