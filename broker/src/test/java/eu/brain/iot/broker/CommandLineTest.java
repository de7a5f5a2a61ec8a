package eu.brain.iot.broker;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;

class CommandLineTest {

    @Test
    void defaultsBindLoopbackOnTheMqttPortWithFilePersistence() throws UsageException {
        BrokerOptions o = CommandLine.parse(new String[0]);
        assertThat(o.bind()).isEqualTo("127.0.0.1");
        assertThat(o.port()).isEqualTo(1883);
        assertThat(o.persistence()).isEqualTo(BrokerOptions.Persistence.FILE);
        assertThat(o.dataDir()).isEqualTo(BrokerOptions.defaultDataDir());
        assertThat(o.maxQueued()).isEqualTo(BrokerOptions.DEFAULT_MAX_QUEUED);
    }

    @Test
    void readsEveryFlagInBothForms() throws UsageException {
        BrokerOptions o = CommandLine.parse(new String[] {"--port", "27010", "--bind=0.0.0.0", "--data", "/tmp/b",
            "--in-memory", "--max-queued=5"});
        assertThat(o.port()).isEqualTo(27010);
        assertThat(o.bind()).isEqualTo("0.0.0.0");
        assertThat(o.dataDir()).isEqualTo(Path.of("/tmp/b"));
        assertThat(o.persistence()).isEqualTo(BrokerOptions.Persistence.IN_MEMORY);
        assertThat(o.maxQueued()).isEqualTo(5);
    }

    @Test
    void badInputSaysWhichFlagAndWhatItNeeds() {
        assertThatThrownBy(() -> CommandLine.parse(new String[] {"--port", "70000"}))
                .hasMessage("--port needs a whole number 1..65535, found '70000'");
        assertThatThrownBy(() -> CommandLine.parse(new String[] {"--port=abc"}))
                .hasMessage("--port needs a whole number 1..65535, found 'abc'");
        assertThatThrownBy(() -> CommandLine.parse(new String[] {"--data"})).hasMessage("--data needs a value");
        assertThatThrownBy(() -> CommandLine.parse(new String[] {"--bind", "a b"}))
                .hasMessage("--bind needs an address or host name, found 'a b'");
        assertThatThrownBy(() -> CommandLine.parse(new String[] {"--in-memory=yes"}))
                .hasMessage("--in-memory takes no value, found '--in-memory=yes'");
        assertThatThrownBy(() -> CommandLine.parse(new String[] {"--verbose"}))
                .hasMessage("unknown argument '--verbose'");
    }

    @Test
    void theConfigurationFileTurnsUsageStatisticsOffAndNamesTheListener() {
        String xml = BrokerConfigFile.xml(BrokerOptions.defaults().withPort(27011)
                .withPersistence(BrokerOptions.Persistence.IN_MEMORY));
        assertThat(xml).contains("<port>27011</port>", "<bind-address>127.0.0.1</bind-address>",
                "<mode>in-memory</mode>", "<max-queue-size>100000</max-queue-size>")
                .containsPattern("<anonymous-usage-statistics>\\s*<enabled>false</enabled>");
    }
}
