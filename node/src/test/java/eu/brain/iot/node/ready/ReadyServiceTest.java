package eu.brain.iot.node.ready;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/** The ready line's extra services, as the node's bndrun writes them. */
class ReadyServiceTest {

    @Test
    void namesWithAnOptionalConfigurationPid() {
        assertThat(ReadyService.parse(" a.B;pid=x.y , c.D,, ")).containsExactly(new ReadyService("a.B", "x.y"),
                new ReadyService("c.D", null));
        assertThat(ReadyService.parse(null)).isEmpty();
        assertThat(ReadyService.parse("")).isEmpty();
    }
}
