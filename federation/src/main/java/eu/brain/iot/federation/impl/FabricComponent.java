package eu.brain.iot.federation.impl;

import java.io.IOException;
import java.net.InetAddress;
import java.net.UnknownHostException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Hashtable;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicBoolean;

import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.osgi.framework.Constants;
import org.osgi.framework.Filter;
import org.osgi.framework.FrameworkEvent;
import org.osgi.framework.FrameworkListener;
import org.osgi.framework.FrameworkUtil;
import org.osgi.framework.InvalidSyntaxException;
import org.osgi.framework.ServiceReference;
import org.osgi.framework.ServiceRegistration;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.ConfigurationPolicy;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.component.annotations.ReferenceCardinality;
import org.osgi.service.component.annotations.ReferencePolicy;
import org.osgi.service.component.annotations.ReferencePolicyOption;
import org.osgi.service.log.Logger;
import org.osgi.service.log.LoggerFactory;
import org.osgi.service.metatype.annotations.Designate;
import org.osgi.util.tracker.ServiceTracker;

import eu.brain.iot.bis.api.BundleInstaller;
import eu.brain.iot.eventing.annotation.SmartBehaviourNamespace;
import eu.brain.iot.eventing.api.SmartBehaviour;
import eu.brain.iot.eventing.api.UntypedSmartBehaviour;
import eu.brain.iot.eventing.spi.EventForwarder;
import eu.brain.iot.eventing.spi.RemoteEvents;
import eu.brain.iot.federation.api.FabricProperties;
import eu.brain.iot.federation.monitoring.api.FabricMonitor;
import eu.brain.iot.federation.monitoring.api.FabricStatus;

/**
 * A node's membership in a fabric, as a Declarative Services component: active only with its configuration (PID
 * {@value FabricConfig#PID}); without it the node runs alone. It follows the node's smart behaviours (their consumed
 * types and filters, the whole whiteboard but the consumers of last resort) as its interest, registers the forwarders
 * the fabric asks for as {@link EventForwarder} services, and gives events from other nodes to the bus's
 * {@link RemoteEvents}. While the node has its own {@link BundleInstaller}, it registers the fabric's one
 * ({@link FabricInstaller}, ranked higher), through which the node's BMS asks the fabric which node installs. It is
 * the node's {@link FabricMonitor} too (this node, its connection and every other node it knows; see {@link Monitor}).
 * <p>
 * A node without a usable key or state folder does not join: the component stays active with no fabric node and says
 * why (log, {@code fabric:nodes}, {@link FabricMonitor}). Threads: SCR's (activation), the framework's service events
 * (the tracker, which hands the interest to the fabric node's own thread), and the fabric node's (see
 * {@link FabricNode}).
 */
@Component(service = { FabricComponent.class, FabricMonitor.class }, configurationPid = FabricConfig.PID,
        configurationPolicy = ConfigurationPolicy.REQUIRE, immediate = true)
@Designate(ocd = FabricConfig.class)
public final class FabricComponent implements Host, FabricMonitor {

    /** Framework property naming the node when the configuration does not. */
    public static final String NODE_NAME_PROPERTY = "fabric.node.name";
    /** Framework property naming the node's fabric state folder when the configuration does not. */
    public static final String STATE_DIR_PROPERTY = "fabric.node.state.dir";
    /** Service property of the fabric's installer (the node's name), and what the node's own installer lacks. */
    public static final String FABRIC_INSTALLER_PROPERTY = "eu.brain.iot.fabric.installer";
    /** The fabric's installer ranks above the node's own (ranked 0 by default), so that the BMS takes it. */
    public static final int FABRIC_INSTALLER_RANKING = 100;

    private final BundleContext context;
    private final RemoteEvents remoteEvents;
    private final Logger log;
    private final FabricNode node;
    private final String problem;
    /** This node's name, fabric and broker as configured: what the monitor says of a node that does not join. */
    private final String nodeName;
    private final String fabricName;
    private final String brokerUri;
    private final Monitor monitor = new Monitor(System::currentTimeMillis);
    private final ServiceTracker<Object, InterestEntry> behaviours;
    /** Whether the node was started (once): by SCR's thread, or the framework's event thread once started. */
    private final AtomicBoolean joining = new AtomicBoolean();
    private final FrameworkListener untilStarted = e -> {
        if (e.getType() == FrameworkEvent.STARTED) {
            join();
        }
    };
    /** The interest of each tracked behaviour; written by the framework's service events (the tracker). */
    private final Map<ServiceReference<Object>, InterestEntry> interest = new ConcurrentHashMap<>();
    /** The fabric's installer while registered (guarded by this component's monitor). */
    private ServiceRegistration<BundleInstaller> installerRegistration;

    @Activate
    public FabricComponent(BundleContext context, FabricConfig config, @Reference RemoteEvents remoteEvents,
            @Reference(service = LoggerFactory.class) Logger log) throws InvalidSyntaxException {
        this.context = context;
        this.remoteEvents = remoteEvents;
        this.log = log;
        FabricNode joined = null;
        String why = null;
        try {
            Settings settings = settings(config, context);
            joined = new FabricNode(settings, this);
        } catch (IOException | IllegalArgumentException | IllegalStateException e) {
            why = e.getMessage() + (e instanceof IOException ? "; the node reads its key and state when it starts or"
                    + " its configuration (" + FabricConfig.PID + ") changes: start it again once they are in place"
                    : "");
            log.error("This node does not join a fabric: {}", why);
        }
        this.node = joined;
        this.problem = why;
        this.nodeName = nodeName(config, context);
        this.fabricName = config.fabric_name();
        this.brokerUri = config.broker_uri();
        // every behaviour that consumes something, but a monitoring consumer that stays local (the dashboard)
        Filter filter = FrameworkUtil.createFilter("(&(|(objectClass=" + SmartBehaviour.class.getName()
                + ")(objectClass=" + UntypedSmartBehaviour.class.getName() + "))("
                + SmartBehaviourNamespace.CONSUMED_PROPERTY + "=*)(!(" + FabricProperties.LOCAL_ONLY + "=true)))");
        this.behaviours = new ServiceTracker<>(context, filter, null) {
            @Override
            public InterestEntry addingService(ServiceReference<Object> ref) {
                InterestEntry e = entry(ref);
                interest.put(ref, e);
                announce();
                return e;
            }

            @Override
            public void modifiedService(ServiceReference<Object> ref, InterestEntry old) {
                interest.put(ref, entry(ref));
                announce();
            }

            @Override
            public void removedService(ServiceReference<Object> ref, InterestEntry old) {
                interest.remove(ref);
                announce();
            }
        };
        if (node != null) {
            behaviours.open();
            announce();
            joinOnceStarted();
        }
    }

    static Settings settings(FabricConfig config, BundleContext context) {
        String name = nodeName(config, context);
        if (config.key_file().isBlank()) {
            throw new IllegalArgumentException("no signing key is configured (key.file in PID " + FabricConfig.PID
                    + "): create one with 'fabric:keygen FILE', copy it to every node, and set key.file");
        }
        String state = config.state_dir();
        if (state.isBlank()) {
            state = context.getProperty(STATE_DIR_PROPERTY);
        }
        Path stateDir = state == null || state.isBlank()
                ? Path.of(System.getProperty("user.home"), ".brain-iot", "federation", config.fabric_name(), name)
                : Path.of(state);
        return new Settings(config.broker_uri(), config.fabric_name(), name, config.username(), config._password(),
                config.tls(), config.trust_store(), config._trust_store_password(), Path.of(config.key_file()),
                stateDir, config.keep_alive_s(), config.session_expiry_s(), config.resend_timeout_ms(),
                config.max_pending(), config.max_age_ms(), config.batch_max_events(), config.install_bid_ms(),
                config.install_timeout_ms(), config.offline_giveup_ms());
    }

    /** The configured name, else the framework property {@value #NODE_NAME_PROPERTY}, else the host name. */
    private static String nodeName(FabricConfig config, BundleContext context) {
        String name = config.node_name();
        if (name.isBlank()) {
            name = context.getProperty(NODE_NAME_PROPERTY);
        }
        return name == null || name.isBlank() ? hostName() : name;
    }

    private static String hostName() {
        try {
            String host = InetAddress.getLocalHost().getHostName().toLowerCase(Locale.ROOT);
            String clean = host.replaceAll("[^a-z0-9._-]", "-");
            return clean.isEmpty() ? "node" : clean;
        } catch (UnknownHostException e) {
            return "node";
        }
    }

    private static InterestEntry entry(ServiceReference<?> ref) {
        Object consumed = ref.getProperty(SmartBehaviourNamespace.CONSUMED_PROPERTY);
        List<String> types = new ArrayList<>();
        if (consumed instanceof String s) {
            types.add(s);
        } else if (consumed instanceof String[] a) {
            types.addAll(List.of(a));
        } else if (consumed instanceof java.util.Collection<?> c) {
            c.forEach(o -> types.add(String.valueOf(o)));
        }
        Object filter = ref.getProperty(SmartBehaviourNamespace.FILTER_PROPERTY);
        return new InterestEntry(types, filter instanceof String f && !f.isBlank() ? f : null); // empty: no filter
    }

    /**
     * Announce the interest of every tracked behaviour. It reads {@link #interest}, not the tracker's own set: inside
     * {@code addingService} the tracker does not hold the service being added yet.
     */
    private void announce() {
        if (node == null) {
            return;
        }
        synchronized (interest) { // one at a time: the last list computed is the last announced
            List<InterestEntry> entries = new ArrayList<>();
            for (InterestEntry e : interest.values()) {
                if (!e.types().isEmpty()) {
                    entries.add(e);
                }
            }
            node.localInterest(entries);
        }
    }

    /** Which devices this node's edge owns, as its install offers tell ({@link EdgeOwnedDevices}); null: none. */
    void ownedDevices(OwnedDevices owned) {
        if (node != null && node.installer() instanceof FabricInstaller f) {
            f.ownedDevices(owned);
        }
    }

    /**
     * The node's own installer (any but the fabric's): while there is one and this node is a member of a fabric,
     * the fabric's installer is registered, ranked above it, so that the BMS asks the fabric which node installs.
     */
    @Reference(service = BundleInstaller.class, cardinality = ReferenceCardinality.OPTIONAL,
            policy = ReferencePolicy.DYNAMIC, policyOption = ReferencePolicyOption.GREEDY,
            target = "(!(" + FABRIC_INSTALLER_PROPERTY + "=*))", unbind = "removeLocalInstaller")
    void setLocalInstaller(BundleInstaller local) {
        if (node == null) {
            return;
        }
        node.localInstaller(local);
        synchronized (this) {
            if (installerRegistration == null) {
                Hashtable<String, Object> props = new Hashtable<>();
                props.put(FABRIC_INSTALLER_PROPERTY, node.name());
                props.put(Constants.SERVICE_RANKING, FABRIC_INSTALLER_RANKING);
                installerRegistration = context.registerService(BundleInstaller.class, node.installer(), props);
            }
        }
    }

    void removeLocalInstaller(BundleInstaller local) {
        if (node == null) {
            return;
        }
        synchronized (this) {
            if (node.installer() instanceof FabricInstaller f && f.local() != local) {
                return; // a greedy replacement was bound first
            }
            node.localInstaller(null);
            unregisterInstaller();
        }
    }

    private synchronized void unregisterInstaller() {
        if (installerRegistration != null) {
            try {
                installerRegistration.unregister();
            } catch (IllegalStateException gone) {
                // unregistered with the bundle already
            }
            installerRegistration = null;
        }
    }

    /**
     * Join the fabric once the framework has started: every bundle of every start level is up, with the behaviours
     * it registers at start-up. A node that joined earlier would take events other nodes kept for its behaviours
     * (after its restart) before those behaviours are back, and have nobody to give them to.
     */
    private void joinOnceStarted() {
        Bundle system = context.getBundle(Constants.SYSTEM_BUNDLE_LOCATION);
        if (system.getState() != Bundle.ACTIVE) {
            log.info("Fabric: this node joins once its framework has started (every start level up)");
            context.addFrameworkListener(untilStarted);
            if (system.getState() != Bundle.ACTIVE) {
                return;
            }
            context.removeFrameworkListener(untilStarted); // started meanwhile
        }
        join();
    }

    private void join() {
        if (joining.compareAndSet(false, true)) {
            node.start();
        }
    }

    @Deactivate
    void deactivate() {
        context.removeFrameworkListener(untilStarted);
        unregisterInstaller();
        if (node != null) {
            behaviours.close();
            node.close();
        }
    }

    /** @return the fabric node, or {@code null} when this node did not join (see {@link #problem()}) */
    FabricNode node() {
        return node;
    }

    /** @return why this node did not join, or {@code null} */
    String problem() {
        return problem;
    }

    @Override
    public FabricStatus status() {
        if (node == null) {
            return monitor.read(nodeName, fabricName, brokerUri, FabricStatus.NOT_JOINED, problem, List.of(), null);
        }
        return monitor.read(node.name(), node.settings().fabric(), node.settings().brokerUri(),
                node.joined() ? FabricStatus.ONLINE : FabricStatus.JOINING, null, node.nodes(), installed());
    }

    @Override
    public long unverifiedRefused() {
        return node == null ? 0 : node.unverified().refused();
    }

    /** How many behaviours the node's own installer installed; {@code null} without one, or one going away. */
    private Integer installed() {
        BundleInstaller local = node.installer() instanceof FabricInstaller f ? f.local() : null;
        try {
            return local == null ? null : local.installed().size();
        } catch (RuntimeException going) {
            return null; // its bundle is stopping: the next reading goes without it
        }
    }

    @Override
    public RemoteEvents remoteEvents() {
        return remoteEvents;
    }

    @Override
    public AutoCloseable addForwarder(String destination, InterestEntry entry, EventForwarder forwarder) {
        Hashtable<String, Object> props = new Hashtable<>();
        props.put(SmartBehaviourNamespace.CONSUMED_PROPERTY, entry.types().toArray(String[]::new));
        if (entry.filter() != null) {
            props.put(SmartBehaviourNamespace.FILTER_PROPERTY, entry.filter());
        }
        props.put(EventForwarder.DESTINATION_PROPERTY, destination);
        ServiceRegistration<EventForwarder> reg = context.registerService(EventForwarder.class, forwarder, props);
        return () -> {
            try {
                reg.unregister();
            } catch (IllegalStateException gone) {
                // unregistered with the bundle already
            }
        };
    }

    @Override
    public void warn(String message, Object... args) {
        log.warn(message, args);
    }

    @Override
    public void info(String message, Object... args) {
        log.info(message, args);
    }
}
