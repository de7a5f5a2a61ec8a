/**
 * The events of the edge (the sensiNact-style gateway between the fabric and the robot fleet): what it publishes
 * when a robot or a door changes, the command events it consumes, and the outcome it publishes for each command.
 * Smart behaviours compile against this package.
 */
@Export
@Version("1.2.0")
package eu.brain.iot.edge.api;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;
