package eu.brain.iot.robotsim.world;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

class PickPlaceTest {
    // robot1 at (1,1), cart1 at (4,1), cart2 at (4,3), storage at (3,2) and (4,2)
    private static final String MAP = "map:\n######\n#RduC#\n#ddss#\n#dduC#\n######\n";

    @Test
    void corkscrewLiftCarriesTheCartToStorageAndPutsItDown() throws Exception {
        Sim sim = Sim.of(MAP);
        Robot r = sim.robot("robot1");
        Cart cart = sim.cart("cart1");
        sim.goTo("robot1", 4, 1);
        Mission pick = sim.commands.pick(r.index());
        sim.step(3);
        assertThat(r.x()).isEqualTo(4);
        assertThat(r.carried()).isEqualTo(-1);
        sim.step(1);
        assertThat(pick.state()).as("corkscrew lift takes 2 steps").isEqualTo(MissionState.RUNNING);
        assertThat(r.running()).isTrue();
        assertThat(r.carried()).isEqualTo(-1);
        sim.step(1);
        assertThat(pick.state()).isEqualTo(MissionState.FINISHED);
        assertThat(r.carried()).isEqualTo(cart.index());
        assertThat(cart.carriedBy()).isEqualTo(r.index());
        assertThat(sim.world.cartAt(4, 1)).isEqualTo(-1);

        sim.goTo("robot1", 3, 2);
        Mission place = sim.commands.place(r.index());
        for (int i = 0; i < 2; i++) {
            sim.step(1);
            assertThat(cart.x()).as("the cart moves along").isEqualTo(r.x());
            assertThat(cart.y()).isEqualTo(r.y());
        }
        assertThat(r.x()).isEqualTo(3);
        assertThat(r.y()).isEqualTo(2);
        sim.step(2);
        assertThat(place.state()).isEqualTo(MissionState.FINISHED);
        assertThat(r.carried()).isEqualTo(-1);
        assertThat(cart.carriedBy()).isEqualTo(-1);
        assertThat(sim.world.cartAt(3, 2)).isEqualTo(cart.index());
        assertThat(sim.world.map().terrain(3, 2).area()).isEqualTo(3);
    }

    @Test
    void pickWithoutACartAndPlaceWithoutCarryingFail() throws Exception {
        Sim sim = Sim.of(MAP);
        int r = sim.index("robot1");
        Mission pick = sim.commands.pick(r);
        Mission place = sim.commands.place(r);
        sim.step(1);
        assertThat(pick.state()).isEqualTo(MissionState.FAILED);
        assertThat(pick.reason()).isEqualTo("no cart at (1,1)");
        assertThat(place.state()).isEqualTo(MissionState.FAILED);
        assertThat(place.reason()).isEqualTo("not carrying a cart");
    }

    @Test
    void secondPickAndPlaceOnACartFail() throws Exception {
        Sim sim = Sim.of(MAP);
        int r = sim.index("robot1");
        sim.goTo("robot1", 4, 1);
        sim.commands.pick(r);
        Mission again = sim.commands.pick(r);
        sim.step(6);
        assertThat(again.state()).isEqualTo(MissionState.FAILED);
        assertThat(again.reason()).isEqualTo("already carrying cart1");
        // cart2 stands at (4,3): a loaded robot cannot get under it
        Mission under = sim.goTo("robot1", 4, 3);
        sim.step(1);
        assertThat(under.state()).isEqualTo(MissionState.FAILED);
        assertThat(under.reason()).contains("for a robot carrying a cart");
    }

    @Test
    void unloadedRobotDrivesUnderCartsButALoadedOneGoesAround() throws Exception {
        Sim sim = Sim.of("map:\n#######\n#RCuuC#\n#uuuuu#\n#######\n");
        Robot r = sim.robot("robot1");
        sim.goTo("robot1", 5, 1);
        sim.step(1);
        assertThat(r.x()).as("passes under cart1").isEqualTo(2);
        assertThat(r.y()).isEqualTo(1);
        sim.step(3);
        sim.commands.pick(r.index());
        sim.step(2);
        assertThat(r.carried()).isEqualTo(sim.cart("cart2").index());
        Mission back = sim.goTo("robot1", 1, 1);
        sim.step(1);
        sim.step(20);
        assertThat(back.state()).isEqualTo(MissionState.FINISHED);
        assertThat(r.x()).isEqualTo(1);
        assertThat(sim.cart("cart1").x()).isEqualTo(2);
        assertThat(sim.world.cartAt(2, 1)).isEqualTo(sim.cart("cart1").index());
    }

    @Test
    void cancellingAPickLeavesTheCartOnTheFloor() throws Exception {
        Sim sim = Sim.of(MAP);
        int r = sim.index("robot1");
        sim.goTo("robot1", 4, 1);
        sim.step(3);
        Mission pick = sim.commands.pick(r);
        sim.step(1);
        sim.commands.cancel(r, MissionType.PICK, null);
        sim.step(3);
        assertThat(pick.reason()).isEqualTo("cancelled");
        assertThat(sim.world.cartAt(4, 1)).isEqualTo(sim.cart("cart1").index());
        assertThat(sim.robot("robot1").carried()).isEqualTo(-1);
    }

    @Test
    void placeInADoorwayOrOnAnotherCartFails() throws Exception {
        Sim sim = Sim.of("door-open-steps: 0\nmap:\n#####\n#RC##\n##D##\n#uCu#\n#####\n");
        int r = sim.index("robot1");
        sim.commands.door(0, true);
        sim.goTo("robot1", 2, 1);
        sim.commands.pick(r);
        sim.step(3);
        assertThat(sim.robot("robot1").carried()).isGreaterThanOrEqualTo(0);
        sim.goTo("robot1", 2, 2);
        Mission inDoorway = sim.commands.place(r);
        sim.step(2);
        assertThat(inDoorway.reason()).isEqualTo("a cart may not be put down in a doorway");
        assertThat(sim.world.cartCount()).isEqualTo(2);
    }
}
