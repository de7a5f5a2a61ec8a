package eu.brain.iot.eventing.annotation;

import java.lang.annotation.Documented;
import java.lang.annotation.ElementType;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;

import org.osgi.annotation.bundle.Attribute;
import org.osgi.annotation.bundle.Capability;
import org.osgi.service.component.annotations.ComponentPropertyType;

/**
 * Declares a smart behaviour: applied to a Declarative Services component that provides
 * {@link eu.brain.iot.eventing.api.SmartBehaviour} or {@link eu.brain.iot.eventing.api.UntypedSmartBehaviour}.
 * <p>
 * As a component property type it becomes the service properties {@code eu.brain.iot.behaviour.consumed}
 * (class names), {@code eu.brain.iot.behaviour.filter}, {@code .author}, {@code .name} and {@code .description},
 * which the event bus reads. At build time bnd also turns it into a capability in namespace
 * {@value SmartBehaviourNamespace#NAMESPACE} whose attribute {@code consumed} lists the consumed type names, so
 * that a repository index can find the bundle by the events it consumes.
 */
@ComponentPropertyType
@Capability(namespace = SmartBehaviourNamespace.NAMESPACE)
@Documented
@Retention(RetentionPolicy.CLASS)
@Target(ElementType.TYPE)
public @interface SmartBehaviourDefinition {

    /** Prefix of the generated component properties. */
    String PREFIX_ = SmartBehaviourNamespace.PROPERTY_PREFIX;

    /** The event types this behaviour consumes; subtypes of these are delivered as well. */
    @Attribute(SmartBehaviourNamespace.CONSUMED)
    Class<?>[] consumed();

    /**
     * An LDAP filter over the event's fields (for example {@code (robotId=robot1)}); only matching events are
     * delivered. Empty means every event of the consumed types.
     */
    String filter() default "";

    @Attribute(SmartBehaviourNamespace.AUTHOR)
    String author() default "";

    @Attribute(SmartBehaviourNamespace.NAME)
    String name() default "";

    @Attribute(SmartBehaviourNamespace.DESCRIPTION)
    String description() default "";
}
