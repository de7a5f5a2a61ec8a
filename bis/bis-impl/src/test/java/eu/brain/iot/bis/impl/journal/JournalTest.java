package eu.brain.iot.bis.impl.journal;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class JournalTest {

    @TempDir
    Path dir;

    @Test
    void whatIsSavedIsLoadedBackAwkwardCharactersIncluded() throws Exception {
        Journal journal = new Journal(dir.resolve("node"));
        BehaviourRecord record = new BehaviourRecord("eu.x.door", "1.2.3.q", List.of("a.B", "c.D"),
                "http://127.0.0.1:8/index.xml", 1234, "event a.B had no consumer,\tsee 100%\nreally",
                List.of(new BundleFact("eu.x.door", "1.2.3.q", "ab", "file:/r/door 1.jar"),
                        new BundleFact("eu.x.events", "1.0.0", "cd", "file:/r/events.jar")));
        journal.save(new Journal.State(List.of(record), Map.of("eu.x.robot", "removed, by Ann")));
        journal.history("installed", "eu.x.door", "1.2.3.q", "why");

        Journal.State loaded = new Journal(dir.resolve("node")).load();

        assertThat(loaded.behaviours()).containsExactly(record);
        assertThat(loaded.blocked()).containsEntry("eu.x.robot", "removed, by Ann");
        assertThat(Files.readString(dir.resolve("node/history.log"))).contains("installed\teu.x.door\t1.2.3.q\twhy");
    }

    @Test
    void noJournalIsAnEmptyOneAndABrokenLineIsNamed() throws IOException {
        Journal journal = new Journal(dir);
        assertThat(journal.load().behaviours()).isEmpty();

        Files.writeString(dir.resolve("journal.tsv"), "# header\nbehaviour\tonly-two-fields\n");
        assertThatThrownBy(journal::load).hasMessageContaining("journal.tsv:2").hasMessageContaining("fix or delete");
    }
}
