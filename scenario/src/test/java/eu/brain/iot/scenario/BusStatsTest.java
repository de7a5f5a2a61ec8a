package eu.brain.iot.scenario;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.Test;

class BusStatsTest {
    private static final String HEADER = "EVENT TYPE                              PUBLISHED DELIVERED FAILED UNHANDLED"
            + " DISCARDED HELD";

    @Test
    void theEdgesCommandsAndTheirOutcomesAreCountedFromTheTablesPublishedColumn() {
        BusStats bus = BusStats.parse(List.of(HEADER,
                "eu.brain.iot.edge.api.CommandOutcome   12 12 0 0 0 0",
                "eu.brain.iot.edge.api.CloseDoorCommand  4  4 0 0 0 0",
                "eu.brain.iot.edge.api.GoToCommand       8  8 0 0 0 0",
                "eu.brain.iot.edge.api.RobotPositionChanged 300 300 0 0 0 0",
                "BEHAVIOUR BUNDLE QUEUED"));

        assertThat(bus.commandsPublished()).isEqualTo(12);
        assertThat(bus.outcomesPublished()).isEqualTo(12);
        assertThat(bus.totalPublished()).isEqualTo(324);
        assertThat(bus.everyCommandAnswered()).isTrue();
    }

    @Test
    void aCommandWhoseOutcomeIsNotCountedYetIsNotAnswered() {
        BusStats bus = BusStats.parse(List.of(HEADER,
                "eu.brain.iot.edge.api.CommandOutcome   11 11 0 0 0 0",
                "eu.brain.iot.edge.api.CloseDoorCommand  4  4 0 0 0 0",
                "eu.brain.iot.edge.api.GoToCommand       8  8 0 0 0 0"));

        assertThat(bus.everyCommandAnswered()).isFalse();
    }

    @Test
    void theNodesCountersAreSummedTypeByType() {
        BusStats node1 = BusStats.parse(List.of(HEADER,
                "eu.brain.iot.edge.api.CommandOutcome   5 5 0 0 0 0",
                "eu.brain.iot.edge.api.GoToCommand       5 5 0 0 0 0"));
        BusStats node2 = BusStats.parse(List.of(HEADER,
                "eu.brain.iot.edge.api.CommandOutcome   3 3 0 0 0 0",
                "eu.brain.iot.edge.api.OpenDoorCommand   3 3 0 0 0 0",
                "eu.brain.iot.federation.api.DeviceLease 40 40 0 0 0 0"));

        BusStats sum = BusStats.parse(List.of()).plus(node1).plus(node2);

        assertThat(sum.published()).containsEntry("eu.brain.iot.edge.api.CommandOutcome", 8L)
                .containsEntry("eu.brain.iot.federation.api.DeviceLease", 40L);
        assertThat(sum.commandsPublished()).isEqualTo(8);
        assertThat(sum.totalPublished()).isEqualTo(56);
        assertThat(sum.everyCommandAnswered()).isTrue();
    }
}
