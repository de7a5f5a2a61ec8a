/**
 * Annotations that declare smart behaviours, as Declarative Services component property types that also
 * emit the {@code eu.brain.iot.behaviour} capability.
 */
@Export
@Version("1.0.0")
package eu.brain.iot.eventing.annotation;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;
