package eu.brain.iot.bis.impl.repo;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.net.URI;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.osgi.resource.Resource;

/** Parses the real index that bnd's indexer wrote for the tests (target/test-repository). */
class IndexParserTest {

    private static final Path REPOSITORY = Path.of(System.getProperty("bis.test.repository", "target/test-repository"));

    @Test
    void readsTheBehavioursTheirContentAndWhatTheyConsume() throws Exception {
        Path index = REPOSITORY.resolve("index.xml");
        List<Resource> resources = IndexParser.parse(Files.readAllBytes(index), index.toUri());
        List<BehaviourResource> facts = resources.stream()
                .flatMap(r -> BehaviourResource.of(r, index.toUri()).stream()).toList();

        assertThat(facts).extracting(BehaviourResource::symbolicName).containsExactlyInAnyOrder(
                "eu.brain.iot.behaviours.door", "eu.brain.iot.behaviours.robot",
                "eu.brain.iot.behaviours.orchestrator", "eu.brain.iot.behaviours.events",
                "eu.brain.iot.behaviours.warehouse", "eu.brain.iot.edge.api",
                "eu.brain.iot.edge.model.api");
        BehaviourResource door = facts.stream().filter(f -> f.symbolicName().endsWith(".door")).findFirst()
                .orElseThrow();
        assertThat(door.isBehaviour()).isTrue();
        assertThat(door.consumed()).contains("eu.brain.iot.behaviours.events.DoorBehaviorClosed");
        assertThat(door.sha256()).hasSize(64).isLowerCase();
        assertThat(Path.of(door.url())).exists().hasParent(REPOSITORY.toAbsolutePath());
        assertThat(door.size()).isEqualTo(Files.size(Path.of(door.url())));
        BehaviourResource events = facts.stream().filter(f -> f.symbolicName().endsWith(".events")).findFirst()
                .orElseThrow();
        assertThat(events.isBehaviour()).as("the events bundle is a library, no behaviour").isFalse();
        assertThat(facts).filteredOn(f -> f.symbolicName().startsWith("eu.brain.iot.edge."))
                .as("the edge's API bundles, which the behaviours import, are libraries").hasSize(2)
                .noneMatch(BehaviourResource::isBehaviour);
    }

    @Test
    void readsTheGzippedIndexAlike() throws Exception {
        Path gz = REPOSITORY.resolve("index.xml.gz");
        assertThat(IndexParser.parse(Files.readAllBytes(gz), gz.toUri())).hasSize(7);
    }

    @Test
    void aMalformedIndexIsReportedWithItsLocation() {
        byte[] broken = "<repository xmlns='http://www.osgi.org/xmlns/repository/v1.0.0'>\n<resource>\n</repo>"
                .getBytes();
        assertThatThrownBy(() -> IndexParser.parse(broken, URI.create("file:/somewhere/index.xml")))
                .isInstanceOf(IndexException.class).hasMessageContaining("file:/somewhere/index.xml:3:")
                .hasMessageContaining("not a valid R5 index");
    }
}
