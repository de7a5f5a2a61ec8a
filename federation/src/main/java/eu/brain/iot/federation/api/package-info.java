/**
 * The events the fabric's own components exchange between nodes: device leases. Since 1.1, the service property by
 * which a consumer on the bus stays local ({@link eu.brain.iot.federation.api.FabricProperties#LOCAL_ONLY}).
 */
@Export
@Version("1.1.0")
package eu.brain.iot.federation.api;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;
