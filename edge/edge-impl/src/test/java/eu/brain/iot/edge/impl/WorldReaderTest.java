package eu.brain.iot.edge.impl;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;

import eu.brain.iot.edge.api.GoToCommand;
import eu.brain.iot.edge.api.PickCartCommand;
import eu.brain.iot.edge.model.api.ProviderSnapshot;
import eu.brain.iot.edge.model.api.ResourceValue;

/** The carts and the map read from the fleet's world are providers of the device model, and follow the world. */
class WorldReaderTest {

    @RegisterExtension
    final EdgeOnSim fleet = new EdgeOnSim(url -> FleetSettings.of(url, List.of(), List.of(), 100, 1000, 8, 1, 2, 400)
            .withWorldPeriod(100));

    private Object value(String provider, String service, String resource) {
        return fleet.edge.resource(provider, service, resource).map(ResourceValue::value).orElse(null);
    }

    @Test
    void cartsAndMapAreProviders() {
        fleet.awaitAllOk(4 + 3 + 1); // 3 robots, 1 door, 3 carts, the map
        ProviderSnapshot map = fleet.edge.provider("warehouse").orElseThrow();
        assertThat(map.kind()).isEqualTo("warehouse");
        assertThat(value("warehouse", "map", "width")).isEqualTo(20);
        assertThat(value("warehouse", "map", "height")).isEqualTo(10);
        String rows = (String) value("warehouse", "map", "rows");
        assertThat(rows.split("\n")).hasSize(10).allMatch(r -> r.length() == 20);
        assertThat(rows.split("\n")[5].charAt(9)).isEqualTo('D');
        assertThat(fleet.edge.provider("cart1").orElseThrow().kind()).isEqualTo("cart");
        assertThat(value("cart1", "position", "x")).isEqualTo(3);
        assertThat(value("cart1", "position", "y")).isEqualTo(7);
        assertThat(value("cart1", "cart", "carriedBy")).isNull();
    }

    @Test
    void aLiftedCartShowsItsRobot() {
        fleet.awaitAllOk(8);
        // open the door, send robot3 under cart2 (10,7) and lift it
        fleet.edge.act("door1", "control", "open", java.util.Map.of()).toCompletableFuture().join();
        GoToCommand go = new GoToCommand();
        go.deviceId = "robot3";
        go.x = 10;
        go.y = 7;
        assertThat(fleet.edge.execute(go).join().accepted).isTrue();
        PickCartCommand pick = new PickCartCommand();
        pick.deviceId = "robot3";
        assertThat(fleet.edge.execute(pick).join().accepted).isTrue();
        fleet.sim.step(40);
        await().atMost(EdgeOnSim.DEADLINE).until(() -> "robot3".equals(value("cart2", "cart", "carriedBy")));
        assertThat(value("cart2", "position", "x")).isEqualTo(10);
    }
}
