/**
 * The events the fabric's own components exchange between nodes: device leases.
 */
@Export
@Version("1.0.0")
package eu.brain.iot.federation.api;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;
