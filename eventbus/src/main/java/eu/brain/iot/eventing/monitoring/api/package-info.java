/** Monitoring of the event bus: statistics per event type and per consumer. */
@Export
@Version("1.2.0")
package eu.brain.iot.eventing.monitoring.api;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;
