/**
 * The warehouse as the behaviours' extern functions see it: the grid read from the edge's {@code warehouse} provider
 * (cells, areas, shortest paths, the search for free cells), the fleet view built from the edge's device model, the
 * ledger of commands sent through the edge, the robot names, the thread that owns a binding's state and the table
 * from event to the input that thread handles. Hand-written, shared by the robot, door and orchestrator bundles;
 * depends on the event bus API and the edge's event and device-model APIs.
 */
@Export
@Version("2.6.0")
package eu.brain.iot.behaviours.warehouse;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;
