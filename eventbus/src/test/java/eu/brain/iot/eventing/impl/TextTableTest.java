package eu.brain.iot.eventing.impl;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

import eu.brain.iot.eventing.impl.TextTable.Column;

/** The shell's tables stay aligned however long a name is. */
class TextTableTest {

    @Test
    void longNamesAreCutWithAnEllipsisAndNumbersStayUnderTheirHeaders() {
        String longBundle = "eu.brain.iot.behaviours.a.very.long.bundle.symbolic.name.indeed";
        String table = new TextTable(Column.text("BEHAVIOUR", 12), Column.text("BUNDLE", 20),
                Column.number("QUEUED"), Column.text("CONSUMES", Integer.MAX_VALUE))
                .row("door#1", longBundle, 0, "a.B,a.C")
                .row("a-very-long-behaviour-name#77", "short", 123456, "a.D").toString();
        String[] lines = table.split(System.lineSeparator());
        assertThat(lines).hasSize(3);
        assertThat(lines[1]).contains("eu.brain.iot.beha...").doesNotContain(longBundle);
        assertThat(lines[2]).startsWith("a-very-lo...  ");
        int consumes = lines[0].indexOf("CONSUMES");
        assertThat(lines[1].indexOf("a.B")).isEqualTo(consumes);
        assertThat(lines[2].indexOf("a.D")).isEqualTo(consumes);
        int queuedEnd = lines[0].indexOf("QUEUED") + "QUEUED".length();
        assertThat(lines[1].indexOf(" 0 ") + 2).isEqualTo(queuedEnd);
        assertThat(lines[2].indexOf("123456") + 6).isEqualTo(queuedEnd);
    }
}
