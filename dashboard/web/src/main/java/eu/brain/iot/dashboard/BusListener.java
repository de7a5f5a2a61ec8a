package eu.brain.iot.dashboard;

import java.util.Map;

import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Reference;

import eu.brain.iot.eventing.api.UntypedSmartBehaviour;
import eu.brain.iot.federation.api.FabricProperties;

/**
 * The dashboard's consumer on the bus: the event types of {@link ConsumedTypes#CONSUMED}, by name and as maps, so
 * that the dashboard compiles against no behaviour bundle. The service property below must list exactly that
 * list (a test checks it); it is written out because a component property is a compile-time constant.
 * <p>
 * It stays local ({@link FabricProperties#LOCAL_ONLY}): the dashboard shows what happens on its node, and a node in a
 * fabric does not announce it to the others; announced, it would pull every node's commands and outcomes to each
 * node that runs a dashboard.
 * <p>
 * Thread: called by the bus's workers, one event at a time; it only hands the event to the {@link Hub}.
 */
@Component(service = UntypedSmartBehaviour.class, property = {
        "eu.brain.iot.behaviour.name=Dashboard",
        "eu.brain.iot.behaviour.description=Counts commands, outcomes, obstacles and carts for the live dashboard",
        FabricProperties.LOCAL_ONLY + ":Boolean=true",
        "eu.brain.iot.behaviour.consumed=eu.brain.iot.edge.api.CommandOutcome",
        "eu.brain.iot.behaviour.consumed=eu.brain.iot.edge.api.GoToCommand",
        "eu.brain.iot.behaviour.consumed=eu.brain.iot.edge.api.PickCartCommand",
        "eu.brain.iot.behaviour.consumed=eu.brain.iot.edge.api.PlaceCartCommand",
        "eu.brain.iot.behaviour.consumed=eu.brain.iot.edge.api.OpenDoorCommand",
        "eu.brain.iot.behaviour.consumed=eu.brain.iot.edge.api.CloseDoorCommand",
        "eu.brain.iot.behaviour.consumed=eu.brain.iot.edge.api.CancelMissionCommand",
        "eu.brain.iot.behaviour.consumed=eu.brain.iot.edge.api.ObstacleDetected",
        "eu.brain.iot.behaviour.consumed=eu.brain.iot.edge.api.ObstacleCleared",
        "eu.brain.iot.behaviour.consumed=eu.brain.iot.edge.api.CartLifted",
        "eu.brain.iot.behaviour.consumed=eu.brain.iot.edge.api.CartPlaced",
        "eu.brain.iot.behaviour.consumed=eu.brain.iot.edge.api.MissionFinished",
        "eu.brain.iot.behaviour.consumed=eu.brain.iot.edge.api.MissionFailed",
        "eu.brain.iot.behaviour.consumed=eu.brain.iot.edge.api.DeviceUnreachable",
        "eu.brain.iot.behaviour.consumed=eu.brain.iot.edge.api.DeviceRecovered",
        "eu.brain.iot.behaviour.consumed=eu.brain.iot.bms.api.BehaviourInstalled",
        "eu.brain.iot.behaviour.consumed=eu.brain.iot.bms.api.BehaviourInstallFailed",
        "eu.brain.iot.behaviour.consumed=eu.brain.iot.bms.api.BehaviourNotFound",
        "eu.brain.iot.behaviour.consumed=eu.brain.iot.behaviours.events.TransitionFired" })
public final class BusListener implements UntypedSmartBehaviour {

    private final Hub hub;

    @Activate
    public BusListener(@Reference Hub hub) {
        this.hub = hub;
    }

    @Override
    public void notify(String eventType, Map<String, ?> properties) {
        hub.offer(new Change.BusEvent(eventType, properties));
    }
}
