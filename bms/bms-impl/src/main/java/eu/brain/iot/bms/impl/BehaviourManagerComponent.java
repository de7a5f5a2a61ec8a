package eu.brain.iot.bms.impl;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.function.BooleanSupplier;
import java.util.function.Supplier;

import org.osgi.framework.BundleContext;
import org.osgi.framework.Constants;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.ConfigurationPolicy;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Modified;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.component.annotations.ReferenceCardinality;
import org.osgi.service.component.annotations.ReferencePolicy;
import org.osgi.service.component.annotations.ReferencePolicyOption;
import org.osgi.service.log.Logger;
import org.osgi.service.log.LoggerFactory;
import org.osgi.service.metatype.annotations.Designate;

import eu.brain.iot.bis.api.BundleInstaller;
import eu.brain.iot.bms.impl.TypeState.Installed;
import eu.brain.iot.bms.impl.TypeState.Installing;
import eu.brain.iot.bms.impl.TypeState.Resting;
import eu.brain.iot.bms.impl.TypeState.RetryWait;
import eu.brain.iot.bms.impl.TypeState.Searching;
import eu.brain.iot.bms.monitoring.api.BehaviourManagerStatistics;
import eu.brain.iot.bms.monitoring.api.HistoryEntry;
import eu.brain.iot.bms.monitoring.api.ManagerCounters;
import eu.brain.iot.bms.monitoring.api.PendingType;
import eu.brain.iot.eventing.api.EventBus;
import eu.brain.iot.eventing.spi.HeldEvents;
import eu.brain.iot.eventing.spi.HeldType;
import eu.brain.iot.eventing.spi.UnhandledEventPolicy;

/**
 * The Behaviour Management Service as a Declarative Services component: the bus's {@link UnhandledEventPolicy}
 * and the BMS's statistics. It needs a {@link BundleInstaller} (the best-ranked one: the node's own, or a fabric's
 * that chooses which node installs; see {@link CurrentInstaller}), the bus and the bus's
 * {@link HeldEvents}. A new configuration applies in place ({@code @Modified}): the types being installed and the
 * held events are kept. It listens to the framework's bundle events ({@link BundleWatch}) to bring back a behaviour
 * whose bundle stopped or was uninstalled outside the installer. Threads: {@code brain-iot-bms} (the BMS's decisions
 * after an episode's first event, and after a behaviour's bundle went away), {@code brain-iot-bms-alerts} (publishing
 * alerts) and the framework's event thread (which only queues bundle events); see {@link BehaviourManager}.
 */
@Component(service = { UnhandledEventPolicy.class, BehaviourManagerStatistics.class },
        configurationPid = BehaviourManagerComponent.PID, configurationPolicy = ConfigurationPolicy.OPTIONAL)
@Designate(ocd = BmsConfig.class)
public final class BehaviourManagerComponent implements UnhandledEventPolicy, BehaviourManagerStatistics {

    static final String PID = "eu.brain.iot.bms";

    private final BehaviourManager manager;
    private final ThreadScheduler scheduler;
    private final BundleWatch watch;
    private final ExecutorService alertThread;
    private final ManagerCountersImpl counters = new ManagerCountersImpl();
    private final Logger log;

    /** The best-ranked installer, followed as installers come and go (see {@link #addInstaller}). */
    private final CurrentInstaller installer = new CurrentInstaller();

    @Activate
    public BehaviourManagerComponent(BundleContext context, BmsConfig config, @Reference EventBus bus,
            @Reference HeldEvents held,
            @Reference(service = LoggerFactory.class) Logger log) {
        this.log = log;
        Settings settings = Settings.from(config); // a bad value fails activation with the property's name
        this.scheduler = new ThreadScheduler("brain-iot-bms", log);
        this.alertThread = Executors.newSingleThreadExecutor(r -> {
            Thread t = new Thread(r, "brain-iot-bms-alerts");
            t.setDaemon(true);
            return t;
        });
        BooleanSupplier frameworkStopping = BundleWatch.frameworkStopping(context);
        this.manager = new BehaviourManager(installer, held, scheduler,
                new Alerts(bus, alertThread, log, counters.alerts), log, counters, settings, frameworkStopping);
        this.watch = new BundleWatch(context, scheduler, frameworkStopping, manager::wentAway);
        manager.start();
        watch.open();
    }

    /**
     * Installers as they come and go: the node's own, and a fabric's while the node is a member of one (ranked
     * higher: it asks the other nodes which one installs). Dynamic and greedy, so that the best-ranked one is used
     * without restarting the BMS: a restart would drop the policy from the bus for a moment, and with it the types
     * being installed.
     */
    @Reference(service = BundleInstaller.class, cardinality = ReferenceCardinality.AT_LEAST_ONE,
            policy = ReferencePolicy.DYNAMIC, policyOption = ReferencePolicyOption.GREEDY,
            unbind = "removeInstaller", updated = "addInstaller")
    void addInstaller(BundleInstaller installer, Map<String, Object> properties) {
        Object ranking = properties.get(Constants.SERVICE_RANKING);
        this.installer.add(installer, ranking instanceof Integer r ? r : 0,
                (Long) properties.get(Constants.SERVICE_ID));
    }

    void removeInstaller(BundleInstaller installer, Map<String, Object> properties) {
        this.installer.remove((Long) properties.get(Constants.SERVICE_ID));
    }

    @Modified
    void modified(BmsConfig config) {
        try {
            manager.reconfigure(Settings.from(config));
        } catch (IllegalArgumentException e) {
            log.error("Behaviour Management Service: configuration refused, the previous one stays: {}",
                    e.getMessage());
        }
    }

    @Deactivate
    void deactivate() {
        watch.close();
        scheduler.close();
        alertThread.shutdownNow();
    }

    @Override
    public Disposition unhandled(String eventType, List<String> typeHierarchy) {
        return manager.unhandled(eventType, typeHierarchy, Map::of);
    }

    @Override
    public Disposition unhandled(String eventType, List<String> typeHierarchy,
            Supplier<Map<String, Object>> fields) {
        return manager.unhandled(eventType, typeHierarchy, fields);
    }

    @Override
    public int maxHeldEvents() {
        return manager.maxHeldEvents();
    }

    @Override
    public List<PendingType> pending() {
        return pending(manager.states(), manager.heldNow());
    }

    static List<PendingType> pending(Map<String, TypeState> states, List<HeldType> heldNow) {
        Map<String, Integer> held = new HashMap<>();
        heldNow.forEach(h -> held.put(h.eventType, h.count));
        List<PendingType> list = new ArrayList<>();
        states.forEach((type, state) -> {
            PendingType p = new PendingType();
            p.eventType = type;
            p.searched = state.searched();
            p.since = state.since();
            p.heldEvents = held.getOrDefault(type, 0);
            if (state instanceof Searching s) {
                p.state = "SEARCHING";
                p.attempt = s.attempt() - 1;
            } else if (state instanceof Installing i) {
                p.state = "INSTALLING";
                p.behaviour = i.behaviour();
                p.attempt = i.attempt();
            } else if (state instanceof RetryWait w) {
                p.state = "RETRY_WAIT";
                p.behaviour = w.behaviour();
                p.attempt = w.attempt();
                p.until = w.nextRetry();
                p.lastReason = w.lastReason();
            } else if (state instanceof Installed i) {
                p.state = "INSTALLED";
                p.behaviour = i.behaviour();
                p.until = i.graceUntil();
            } else if (state instanceof Resting r) {
                p.state = r.kind().name();
                p.behaviour = r.behaviour();
                p.until = r.until();
                p.unhandledEvents = r.unhandled().sum();
                p.lastReason = r.reason();
            }
            list.add(p);
        });
        list.sort(Comparator.comparingLong((PendingType p) -> p.since).thenComparing(p -> p.eventType));
        return list;
    }

    @Override
    public List<HistoryEntry> history() {
        return manager.history();
    }

    @Override
    public ManagerCounters counters() {
        return counters.snapshot();
    }
}
