/**
 * The warehouse's grid as the behaviours' extern functions see it (read from the edge's {@code warehouse} provider):
 * cells, areas, the robots' own path planning (breadth-first, as the fleet plans) and the search for free cells.
 * Hand-written, shared by the robot, door and orchestrator bundles; no dependency on the edge.
 */
@Export
@Version("1.1.0")
package eu.brain.iot.behaviours.warehouse;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;
