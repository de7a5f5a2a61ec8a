package eu.brain.iot.edge.impl;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.CompletionStage;

import org.osgi.framework.BundleContext;
import org.osgi.framework.Constants;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.ConfigurationPolicy;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Modified;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.log.Logger;
import org.osgi.service.log.LoggerFactory;
import org.osgi.service.metatype.annotations.Designate;

import eu.brain.iot.edge.api.CommandOutcome;
import eu.brain.iot.edge.api.DeviceReport;
import eu.brain.iot.edge.api.EdgeCommand;
import eu.brain.iot.edge.model.api.DeviceModel;
import eu.brain.iot.edge.model.api.DeviceOwnership;
import eu.brain.iot.edge.model.api.PollMonitor;
import eu.brain.iot.edge.model.api.PollStatistics;
import eu.brain.iot.edge.model.api.ProviderSnapshot;
import eu.brain.iot.edge.model.api.ResourceListener;
import eu.brain.iot.edge.model.api.ResourceValue;
import eu.brain.iot.eventing.annotation.SmartBehaviourDefinition;
import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.eventing.api.EventBus;
import eu.brain.iot.eventing.api.SmartBehaviour;

/**
 * The edge as a Declarative Services component: the {@link DeviceModel} and {@link PollMonitor} services, and a
 * smart behaviour that consumes {@link EdgeCommand}s. Configured by Config Admin (PID {@value EdgeConfig#PID}); a
 * new configuration is applied in place (devices added and removed, nothing restarted). It registers API types
 * only (the edge's and the eventing API's) and depends on the framework-free core ({@link Edge}), never the other
 * way.
 * <p>
 * Immediate: it polls the fleet whether or not anyone uses its services yet. (As a delayed component, SCR built it
 * for its first user and threw it away when that user let go, at every boot: the event bus looks behaviours up
 * before the REST API binds the device model, so the edge started twice and its first poll raced its closing.)
 */
@Component(service = { DeviceModel.class, SmartBehaviour.class, PollMonitor.class, DeviceOwnership.class },
        configurationPid = EdgeConfig.PID, configurationPolicy = ConfigurationPolicy.OPTIONAL, immediate = true)
@SmartBehaviourDefinition(consumed = { EdgeCommand.class, DeviceReport.class }, author = "BRAIN-IoT fabric",
        name = "sensiNact edge", description = "Performs robot and door commands over the fleet's REST API, and shows"
                + " the devices other nodes of a shared fleet report")
@Designate(ocd = EdgeConfig.class)
public final class EdgeComponent implements DeviceModel, SmartBehaviour<BrainIoTEvent>, PollMonitor, DeviceOwnership {

    private final Edge edge;
    private final Logger log;
    /** This framework's UUID: the bus names it as the source of the events published here. */
    private final String frameworkUuid;

    /**
     * Framework property: the fleet's URL when the configuration sets no {@code fleet.url} (so that
     * {@code ./fabric-node --fleet-port=N} points the edge at the robot-sim it started on another port).
     */
    static final String FLEET_URL_PROPERTY = "eu.brain.iot.edge.fleet.url";

    /** The framework property's value, or null. */
    private final String frameworkFleetUrl;

    @Activate
    public EdgeComponent(EdgeConfig config, BundleContext context,
            @Reference EventBus bus, @Reference(service = LoggerFactory.class) Logger log) {
        this.log = log;
        this.frameworkFleetUrl = context.getProperty(FLEET_URL_PROPERTY);
        this.frameworkUuid = context.getProperty(Constants.FRAMEWORK_UUID);
        FleetSettings settings = checked(config);
        String node = nodeName(context.getProperty(EdgeNode.PROPERTY));
        this.edge = new Edge(settings, node, bus::tryDeliver, EdgeLog.of(log));
        log.info("edge polling the fleet at " + settings.baseUrl() + " every " + settings.periodMillis()
                + " ms for node " + node + ", its share: " + settings.share());
    }

    @Modified
    void modified(EdgeConfig config) {
        try {
            edge.configure(FleetSettings.from(config, fleetUrl(config, frameworkFleetUrl)));
        } catch (IllegalArgumentException e) {
            log.error("configuration " + EdgeConfig.PID + " rejected, the edge keeps its previous one: "
                    + e.getMessage());
        }
    }

    /**
     * The configuration's {@code fleet.url} when it sets another than the default, else the framework property's,
     * else the default. (The component's properties always hold a {@code fleet.url}: bnd adds the defaults of the
     * configuration type, so the default value is what says that none was configured.)
     */
    static String fleetUrl(EdgeConfig config, String frameworkFleetUrl) {
        if (!EdgeConfig.DEFAULT_FLEET_URL.equals(config.fleet_url()) || frameworkFleetUrl == null
                || frameworkFleetUrl.isBlank()) {
            return config.fleet_url();
        }
        return frameworkFleetUrl.trim();
    }

    private FleetSettings checked(EdgeConfig config) {
        try {
            return FleetSettings.from(config, fleetUrl(config, frameworkFleetUrl));
        } catch (IllegalArgumentException e) {
            log.error("configuration " + EdgeConfig.PID + " rejected, the edge does not start: " + e.getMessage());
            throw e;
        }
    }

    private String nodeName(String property) {
        try {
            return EdgeNode.name(property);
        } catch (IllegalArgumentException e) {
            log.error("the edge does not start: " + e.getMessage());
            throw e;
        }
    }

    @Deactivate
    void deactivate() {
        edge.close();
    }

    @Override
    public void notify(BrainIoTEvent event) {
        if (event instanceof EdgeCommand command) {
            edge.execute(command, command.sourceNode == null || command.sourceNode.equals(frameworkUuid));
        } else if (event instanceof DeviceReport report) {
            edge.reported(report);
        }
    }

    @Override
    public List<ProviderSnapshot> providers() {
        return edge.providers();
    }

    @Override
    public Optional<ProviderSnapshot> provider(String providerId) {
        return edge.provider(providerId);
    }

    @Override
    public Optional<ResourceValue> resource(String providerId, String service, String resource) {
        return edge.resource(providerId, service, resource);
    }

    @Override
    public Subscription subscribe(String providerId, String service, ResourceListener listener) {
        return edge.subscribe(providerId, service, listener);
    }

    @Override
    public CompletionStage<CommandOutcome> act(String providerId, String service, String action,
            Map<String, Object> parameters) {
        return edge.act(providerId, service, action, parameters);
    }

    @Override
    public PollStatistics statistics() {
        return edge.statistics();
    }

    @Override
    public String nodeName() {
        return edge.ownership().nodeName();
    }

    @Override
    public Set<String> owned() {
        return edge.ownership().owned();
    }

    @Override
    public Set<String> share() {
        return edge.ownership().share();
    }

    @Override
    public Set<String> fleet() {
        return edge.ownership().fleet();
    }

    @Override
    public boolean owns(String deviceId) {
        return edge.ownership().owns(deviceId);
    }

    @Override
    public Set<String> take(Set<String> deviceIds) {
        return edge.ownership().take(deviceIds);
    }

    @Override
    public Set<String> release(Set<String> deviceIds) {
        return edge.ownership().release(deviceIds);
    }

    @Override
    public boolean atRest(String deviceId) {
        return edge.atRest(deviceId);
    }
}
