/**
 * Monitoring of a node's membership in a fabric: this node's connection to the broker and every other node it knows,
 * with its presence, its interest and what passed between the two. Provided by the federation bundle
 * ({@link FabricMonitor}, registered while the node has a fabric configuration); read by the dashboard. Since 1.1,
 * the total of messages refused from names no verified message came from ({@link FabricMonitor#unverifiedRefused}).
 */
@Export
@Version("1.1.0")
package eu.brain.iot.federation.monitoring.api;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;
