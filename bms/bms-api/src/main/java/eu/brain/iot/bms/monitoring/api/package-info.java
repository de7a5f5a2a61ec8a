/** Monitoring of the Behaviour Management Service: the types waiting for a behaviour, what it did, its counters. */
@Export
@Version("1.0.0")
package eu.brain.iot.bms.monitoring.api;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;
