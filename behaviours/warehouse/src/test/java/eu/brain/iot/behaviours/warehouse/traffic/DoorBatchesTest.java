package eu.brain.iot.behaviours.warehouse.traffic;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

import eu.brain.iot.behaviours.warehouse.traffic.DoorBatches.Way;

class DoorBatchesTest {

    @Test
    void aQueueIsServedInOneBatchThenTheDoorTurns() {
        DoorBatches door = new DoorBatches();
        assertThat(door.decide(3, 1)).isEqualTo(Way.OUT);
        assertThat(door.batchLeft()).isEqualTo(3);
        door.passed(Way.OUT);
        door.passed(Way.OUT);
        assertThat(door.decide(5, 1)).as("the batch was sized when it began").isEqualTo(Way.OUT);
        door.passed(Way.OUT);
        assertThat(door.decide(4, 1)).as("the batch passed: the one waiting the other way").isEqualTo(Way.IN);
        assertThat(door.batchLeft()).isEqualTo(1);
        door.passed(Way.IN);
        assertThat(door.decide(4, 0)).isEqualTo(Way.OUT);
        assertThat(door.batchLeft()).isEqualTo(4);
    }

    @Test
    void anEmptySideTurnsTheDoorAtOnce() {
        DoorBatches door = new DoorBatches();
        assertThat(door.decide(2, 0)).isEqualTo(Way.OUT);
        assertThat(door.decide(0, 2)).isEqualTo(Way.IN);
        assertThat(door.decide(0, 0)).isEqualTo(Way.IN);
    }
}
