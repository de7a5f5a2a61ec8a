package eu.brain.iot.bms.integration;

import static org.assertj.core.api.Assertions.assertThat;
import static org.awaitility.Awaitility.await;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Arrays;
import java.util.Comparator;
import java.util.Dictionary;
import java.util.HashMap;
import java.util.Hashtable;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.osgi.framework.ServiceReference;
import org.osgi.service.cm.Configuration;
import org.osgi.service.cm.ConfigurationAdmin;
import org.osgi.test.common.annotation.InjectBundleContext;
import org.osgi.test.common.annotation.InjectService;

import eu.brain.iot.bis.api.BundleInstaller;
import eu.brain.iot.bis.api.InstalledBehaviour;
import eu.brain.iot.bms.api.BehaviourInstallFailed;
import eu.brain.iot.bms.api.BehaviourInstalled;
import eu.brain.iot.bms.api.BehaviourNotFound;
import eu.brain.iot.bms.integration.tb.Order;
import eu.brain.iot.bms.integration.tb.OrderBehaviourActivator;
import eu.brain.iot.bms.integration.tb.Refill;
import eu.brain.iot.bms.monitoring.api.BehaviourManagerStatistics;
import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.eventing.api.EventBus;
import eu.brain.iot.eventing.api.SmartBehaviour;
import eu.brain.iot.eventing.api.UntypedSmartBehaviour;
import eu.brain.iot.eventing.monitoring.api.EventBusStatistics;
import eu.brain.iot.eventing.monitoring.api.EventTypeStatistics;

/**
 * What the in-framework tests of behaviours installed on demand share: a real index of a real behaviour bundle
 * ({@code tb.bms.orders}, which answers each event with an acknowledgement) in a temporary directory, the Bundle
 * Installer configured with it, the acknowledgements and the BMS's alerts as they arrive, and a clean-up that
 * uninstalls what the installer installed and removes the configurations. The configurations are written here, not
 * with osgi-test's {@code @WithConfiguration}: the index is made per test in a temporary directory, and a placeholder
 * configured before the test would start an installer on the default (the user's) journal directory.
 */
abstract class BmsTestBase {

    static final Duration DEADLINE = Duration.ofSeconds(60);
    static final String ORDERS = "tb.bms.orders";

    @InjectBundleContext
    BundleContext context;
    @InjectService(timeout = 5000)
    ConfigurationAdmin configAdmin;
    @InjectService(timeout = 5000)
    EventBus bus;
    @InjectService(timeout = 5000)
    EventBusStatistics busStatistics;

    Path temp;
    TestRepository repository;
    private Configuration bis;
    private Configuration bms;
    final List<Map<String, Object>> acks = new CopyOnWriteArrayList<>();
    final List<BrainIoTEvent> alerts = new CopyOnWriteArrayList<>();

    @BeforeEach
    void start() throws Exception {
        temp = Files.createTempDirectory("bms-itest");
        repository = TestRepository.create(temp.resolve("repo"), ORDERS, OrderBehaviourActivator.class,
                new String[] { Order.class.getName(), Refill.class.getName() }, Order.class, Refill.class);
        Hashtable<String, Object> ackProps = new Hashtable<>();
        ackProps.put("eu.brain.iot.behaviour.consumed", OrderBehaviourActivator.ACK);
        // registered through the test's CloseableBundleContext: unregistered when the test ends
        context.registerService(UntypedSmartBehaviour.class,
                (UntypedSmartBehaviour) (type, data) -> acks.add(new HashMap<>(data)), ackProps);
        Hashtable<String, Object> alertProps = new Hashtable<>();
        alertProps.put("eu.brain.iot.behaviour.consumed", new String[] { BehaviourNotFound.class.getName(),
                BehaviourInstallFailed.class.getName(), BehaviourInstalled.class.getName() });
        context.registerService(SmartBehaviour.class, (SmartBehaviour<BrainIoTEvent>) alerts::add, alertProps);
    }

    /** Configures the BIS with the test's index (signatures not checked: the BIS's own tests cover trust). */
    BundleInstaller configure() throws Exception {
        bis = configAdmin.getConfiguration("eu.brain.iot.bis", "?");
        Dictionary<String, Object> props = new Hashtable<>();
        props.put("repositories", new String[] { repository.index.toUri().toString() });
        props.put("journal.dir", temp.resolve("journal").toString());
        props.put("refresh.ms", 100L);
        bis.update(props);
        await().atMost(DEADLINE).until(() -> context.getServiceReference(BehaviourManagerStatistics.class) != null);
        BundleInstaller installer = service(BundleInstaller.class);
        await().atMost(DEADLINE).until(() -> !installer.find(List.of(Order.class.getName())).getValue().isEmpty());
        return installer;
    }

    /**
     * Configures the BMS (PID {@code eu.brain.iot.bms}; applied in place), e.g. {@code restart.grace.ms}; removed when
     * the test ends.
     */
    void configureBms(String key, Object value) throws Exception {
        bms = configAdmin.getConfiguration("eu.brain.iot.bms", "?");
        Dictionary<String, Object> props = new Hashtable<>();
        props.put(key, value);
        bms.update(props);
    }

    @AfterEach
    void stop() throws Exception {
        BundleInstaller installer = context.getServiceReference(BundleInstaller.class) == null ? null
                : service(BundleInstaller.class);
        if (installer != null) {
            for (InstalledBehaviour b : installer.installed()) {
                installer.uninstall(b.symbolicName, "test clean-up", false).getValue();
            }
        }
        if (bms != null) {
            bms.delete();
        }
        if (bis != null) {
            bis.delete();
            await().atMost(DEADLINE).until(() -> context.getServiceReference(BundleInstaller.class) == null);
        }
        try (Stream<Path> files = Files.walk(temp)) {
            files.sorted(Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
        }
    }

    /** Publishes orders of publisher "p" with sequence numbers {@code from} (included) to {@code to} (excluded). */
    void publishOrders(int from, int to) {
        for (int seq = from; seq < to; seq++) {
            bus.deliver(order("p", seq));
        }
    }

    void awaitNoConsumerOf(String symbolicName) {
        await().atMost(DEADLINE)
                .until(() -> busStatistics.consumers().stream().noneMatch(c -> symbolicName.equals(c.bundle)));
    }

    /** Calls a bis:* Gogo command as the shell does (the command object is a service) and returns its text. */
    String bisCommand(String function, Object... args) throws Exception {
        return command("bis", function, args);
    }

    /**
     * Calls a Gogo command {@code scope:function} as the shell does and returns its text. The command object is a
     * service of its own, which may come a moment after the service it serves: it is waited for.
     */
    String command(String scope, String function, Object... args) throws Exception {
        ServiceReference<?>[] refs = await().atMost(DEADLINE).until(
                () -> context.getServiceReferences((String) null, "(osgi.command.scope=" + scope + ")"),
                r -> r != null);
        assertThat(refs).as("the %s:* commands", scope).hasSize(1);
        Object commands = context.getService(refs[0]);
        for (var m : commands.getClass().getMethods()) {
            if (m.getName().equals(function) && m.getParameterCount() == args.length) {
                return String.valueOf(m.invoke(commands, args));
            }
        }
        throw new AssertionError("no command " + scope + ":" + function);
    }

    static Order order(String publisher, int seq) {
        Order o = new Order();
        o.publisher = publisher;
        o.seq = seq;
        return o;
    }

    static Refill refill(String publisher, int seq) {
        Refill r = new Refill();
        r.publisher = publisher;
        r.seq = seq;
        return r;
    }

    <T> T service(Class<T> type) {
        ServiceReference<T> ref = context.getServiceReference(type);
        assertThat(ref).as("a %s service", type.getSimpleName()).isNotNull();
        return context.getService(ref);
    }

    <T> List<T> alertsOf(Class<T> type) {
        return alerts.stream().filter(type::isInstance).map(type::cast).toList();
    }

    EventTypeStatistics typeStatistics(String type) {
        return busStatistics.eventTypes().stream().filter(s -> s.eventType.equals(type)).findFirst()
                .orElseGet(EventTypeStatistics::new);
    }

    Bundle bundle(String symbolicName) {
        List<Bundle> found = bundles(symbolicName);
        return found.isEmpty() ? null : found.get(0);
    }

    List<Bundle> bundles(String symbolicName) {
        return Arrays.stream(context.getBundles()).filter(b -> symbolicName.equals(b.getSymbolicName())).toList();
    }

    Set<Long> bundleIds() {
        return Arrays.stream(context.getBundles()).map(Bundle::getBundleId).collect(Collectors.toSet());
    }
}
