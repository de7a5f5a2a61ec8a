package eu.brain.iot.eventing.integration.listing3;
import eu.brain.iot.eventing.annotation.SmartBehaviourDefinition;
import eu.brain.iot.eventing.api.BrainIoTEvent;
import eu.brain.iot.eventing.api.SmartBehaviour;
import org.osgi.service.component.annotations.Component;
@Component(service = SmartBehaviour.class)
// The paper's Listing 3, as printed, except line 7: a static field cannot be declared inside a method in
// Java, so it is declared just above the method (the only place where it compiles).
@SmartBehaviourDefinition(consumed = {IresolveCollision .class},
author = "UGA", name = "Smart RobotA",
description = "Implements a remote Smart RobotA.")
public class RobotImpl implements SmartBehaviour<BrainIoTEvent>{
    public static IresolveCollision resolveCollision ;
    public void notify(BrainIoTEvent event) {
        if (event instanceof IresolveCollision) {
            resolveCollision = (IresolveCollision) event;
            synchronized (this) {
                resolveCollision.resolveCollision();
            }
        }
    }
}
