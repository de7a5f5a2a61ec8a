package eu.brain.iot.robotsim.world;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

class DoorTest {
    private static final String MAP = "door-open-steps: 2\nmap:\n#####\n#Rdd#\n##D##\n#uuu#\n#####\n";

    @Test
    void robotStopsInFrontOfTheClosedDoorAndGoesOnWhenItHasOpened() {
        Sim sim = Sim.of(MAP);
        Robot r = sim.robot("robot1");
        Door door = sim.world.door(0);
        Mission m = sim.goTo("robot1", 2, 3);
        sim.step(1);
        assertThat(r.x()).isEqualTo(2);
        sim.step(1);
        assertThat(r.y()).isEqualTo(1);
        assertThat(r.detect()).isEqualTo(2);
        assertThat(r.running()).isFalse();
        assertThat(r.heading()).isEqualTo(Heading.S);
        assertThat(door.state()).isEqualTo(DoorState.CLOSED);

        sim.commands.door(0, true);
        assertThat(door.state()).isEqualTo(DoorState.OPENING);
        sim.step(1);
        assertThat(door.state()).isEqualTo(DoorState.OPENING);
        assertThat(r.y()).isEqualTo(1);
        assertThat(r.detect()).isEqualTo(2);
        sim.step(1);
        assertThat(door.state()).isEqualTo(DoorState.OPEN);
        assertThat(r.y()).as("enters the doorway in the step the door finished opening").isEqualTo(2);
        assertThat(r.detect()).isZero();
        assertThat(r.running()).isTrue();

        sim.commands.door(0, false);
        assertThat(door.state()).as("waits for the doorway to clear").isEqualTo(DoorState.CLOSING);
        sim.step(1);
        assertThat(r.y()).isEqualTo(3);
        assertThat(m.state()).isEqualTo(MissionState.FINISHED);
        sim.step(1);
        assertThat(door.state()).isEqualTo(DoorState.CLOSED);
        assertThat(r.nearMisses()).as("a door is no near miss").isZero();
        assertThat(r.waitSteps()).as("nor a wait behind a robot").isZero();
    }

    @Test
    void openingsCountEveryStartOfOpeningAndNothingElse() {
        Sim sim = Sim.of(MAP);
        Door door = sim.world.door(0);
        sim.commands.door(0, true);
        sim.commands.door(0, true);
        assertThat(door.openings()).as("an opening door asked again").isEqualTo(1);
        sim.step(2);
        sim.commands.door(0, true);
        assertThat(door.openings()).as("an open door asked again").isEqualTo(1);
        sim.commands.door(0, false);
        sim.commands.door(0, false);
        assertThat(door.openings()).isEqualTo(1);
        sim.commands.door(0, true);
        assertThat(door.openings()).isEqualTo(2);

        sim.goTo("robot1", 2, 3);
        sim.step(2);
        assertThat(sim.robot("robot1").y()).isEqualTo(2);
        sim.commands.door(0, false);
        assertThat(door.state()).isEqualTo(DoorState.CLOSING);
        sim.commands.door(0, true);
        assertThat(door.state()).isEqualTo(DoorState.OPEN);
        assertThat(door.openings()).as("closing turned back to open").isEqualTo(3);
    }

    @Test
    void doorOpeningTimeIsConfigurable() {
        Sim sim = Sim.of(MAP, SimRules.DEFAULT.withDoorOpenSteps(5));
        sim.commands.door(0, true);
        sim.step(4);
        assertThat(sim.world.door(0).state()).isEqualTo(DoorState.OPENING);
        assertThat(sim.world.door(0).stepsLeft()).isEqualTo(1);
        sim.step(1);
        assertThat(sim.world.door(0).state()).isEqualTo(DoorState.OPEN);
        Sim instant = Sim.of(MAP, SimRules.DEFAULT.withDoorOpenSteps(0));
        instant.commands.door(0, true);
        assertThat(instant.world.door(0).state()).isEqualTo(DoorState.OPEN);
    }

    @Test
    void closingAnOpeningDoorClosesItAndRepeatedCommandsChangeNothing() {
        Sim sim = Sim.of(MAP);
        Door door = sim.world.door(0);
        sim.commands.door(0, true);
        sim.commands.door(0, true);
        assertThat(door.stepsLeft()).isEqualTo(2);
        sim.commands.door(0, false);
        assertThat(door.state()).isEqualTo(DoorState.CLOSED);
        sim.commands.door(0, false);
        assertThat(door.state()).isEqualTo(DoorState.CLOSED);
    }

    @Test
    void doorClosingInFrontOfARobotStopsIt() {
        Sim sim = Sim.of("door-open-steps: 0\nmap:\n######\n#Rdd##\n###D##\n#uuuu#\n######\n");
        Robot r = sim.robot("robot1");
        sim.commands.door(0, true);
        sim.goTo("robot1", 3, 3);
        sim.step(1);
        sim.commands.door(0, false);
        sim.step(2);
        assertThat(r.x()).isEqualTo(3);
        assertThat(r.y()).isEqualTo(1);
        assertThat(r.detect()).isEqualTo(2);
    }
}
