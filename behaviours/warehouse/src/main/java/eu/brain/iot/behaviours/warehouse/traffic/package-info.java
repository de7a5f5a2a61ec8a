/**
 * The fleet's traffic: a space-time reservation planner in the family of windowed cooperative A* (WHCA*) with
 * priorities that rise while a robot makes no progress and pushes of lower-priority robots out of the way (as PIBT
 * does), over robot-sim's movement rules (one cell per step, four directions, a robot enters only a cell that was
 * empty at the start of the step). Plain Java, no OSGi, no threads of its own: the behaviour that owns a planner
 * calls it from one thread. One class per policy: {@link eu.brain.iot.behaviours.warehouse.traffic.FleetPlanner}
 * (who goes where when; its passage claims decide which way a door or a one-cell lane is driven through),
 * {@link eu.brain.iot.behaviours.warehouse.traffic.MapCheck} (maps the planner refuses).
 */
@Export
@Version("2.0.0")
package eu.brain.iot.behaviours.warehouse.traffic;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;
