package eu.brain.iot.eventing.annotation;

import java.lang.annotation.Documented;
import java.lang.annotation.ElementType;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;

import org.osgi.annotation.bundle.Capability;
import org.osgi.service.component.annotations.ComponentPropertyType;

/**
 * Marks an {@link eu.brain.iot.eventing.api.UntypedSmartBehaviour} component as a consumer of last resort: it
 * receives, as maps, exactly the events that no other behaviour consumes (the Behaviour Management Service uses
 * this to find and install a behaviour for them). Becomes the service property
 * {@code eu.brain.iot.behaviour.consumer.of.last.resort=true}.
 */
@ComponentPropertyType
@Capability(namespace = SmartBehaviourNamespace.NAMESPACE,
        attribute = SmartBehaviourNamespace.LAST_RESORT + ":Boolean=true")
@Documented
@Retention(RetentionPolicy.CLASS)
@Target(ElementType.TYPE)
public @interface ConsumerOfLastResort {

    /** Prefix of the generated component property. */
    String PREFIX_ = SmartBehaviourNamespace.PROPERTY_PREFIX;
}
