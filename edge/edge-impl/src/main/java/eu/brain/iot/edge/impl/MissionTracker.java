package eu.brain.iot.edge.impl;

import java.time.Instant;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.Executor;

import eu.brain.iot.edge.api.MissionFailed;
import eu.brain.iot.edge.api.MissionFinished;
import eu.brain.iot.edge.api.RobotEvent;

/**
 * Announces each mission's end once. A robot's answer shows its running mission, else the next queued, else the
 * last ended, so an end is usually seen in a poll; but a mission can end and the next one start between two
 * polls. Then the robot's history ({@code query_state}) is asked for the mission that vanished.
 * <p>
 * Ownership: the fleet thread calls every method and owns every {@link RobotMissions}; history answers are
 * brought back to it through the fleet executor.
 */
final class MissionTracker {

    /** Mission ids already reported as ended, so that no end is announced twice. */
    private static final int REMEMBERED_MISSIONS = 64;

    /** What the tracker knows of one robot's missions. */
    private static final class RobotMissions {
        /**
         * Mission ends seen while the robot's history is being asked about an earlier mission: announced after
         * it, so that ends come out in the order the missions ended. {@code null} when no query is pending.
         */
        List<RobotAnswer.Mission> heldEnds;
        private final ArrayDeque<Long> reported = new ArrayDeque<>();

        /** @return true the first time a mission id is reported */
        boolean firstReport(long missionId) {
            if (reported.contains(missionId)) {
                return false;
            }
            if (reported.size() == REMEMBERED_MISSIONS) {
                reported.removeFirst();
            }
            reported.addLast(missionId);
            return true;
        }
    }

    private final FleetApi api;
    private final Executor fleet;
    private final Outbox events;
    private final EdgeLog log;
    private final Map<String, RobotMissions> robots = new HashMap<>();

    MissionTracker(FleetApi api, Executor fleet, Outbox events, EdgeLog log) {
        this.api = api;
        this.fleet = fleet;
        this.events = events;
        this.log = log;
    }

    void track(String robotId, RobotAnswer before, RobotAnswer now, Instant at) {
        RobotMissions r = robots.computeIfAbsent(robotId, id -> new RobotMissions());
        RobotAnswer.Mission current = now.mission();
        if (before == null) {
            if (current != null && current.ended()) {
                r.firstReport(current.id()); // ended before the edge was watching: not news
            }
            return;
        }
        RobotAnswer.Mission earlier = before.mission();
        if (earlier != null && !earlier.ended() && (current == null || current.id() != earlier.id())
                && r.heldEnds == null) {
            r.heldEnds = new ArrayList<>();
            askHistory(robotId, r, earlier);
        }
        if (current != null && current.ended()) {
            if (r.heldEnds != null) {
                if (!r.heldEnds.contains(current)) {
                    r.heldEnds.add(current);
                }
            } else if (r.firstReport(current.id())) {
                events.publish(missionEnded(robotId, current, at));
            }
        }
    }

    /** The robot left the model: a history answer still on its way is ignored. */
    void forget(String robotId) {
        robots.remove(robotId);
    }

    private void askHistory(String robotId, RobotMissions r, RobotAnswer.Mission vanished) {
        api.endedMission(robotId, vanished).whenComplete((found, error) -> fleet.execute(() -> historyAnswered(
                robotId, r, vanished, found == null ? Optional.empty() : found,
                error == null ? null : String.valueOf(error.getCause() != null ? error.getCause().getMessage()
                        : error.getMessage()))));
    }

    /** On the fleet thread: announce the vanished mission's end, then the ends held back meanwhile. */
    private void historyAnswered(String robotId, RobotMissions r, RobotAnswer.Mission vanished,
            Optional<RobotAnswer.Mission> ended, String problem) {
        List<RobotAnswer.Mission> held = r.heldEnds;
        r.heldEnds = null;
        if (robots.get(robotId) != r) {
            return; // removed meanwhile
        }
        if (ended.isPresent() && r.firstReport(ended.get().id())) {
            events.publish(missionEnded(robotId, ended.get(), Instant.now()));
        } else if (ended.isEmpty()) {
            log.debug("could not learn how mission " + vanished.id() + " of " + robotId + " ended: "
                    + (problem != null ? problem : "not in its history"));
        }
        for (RobotAnswer.Mission m : held) {
            if (r.firstReport(m.id())) {
                events.publish(missionEnded(robotId, m, Instant.now()));
            }
        }
    }

    /** The event of a mission that ended. */
    static RobotEvent missionEnded(String robotId, RobotAnswer.Mission m, Instant at) {
        if ("finished".equals(m.state())) {
            MissionFinished e = EdgeEvents.robotEvent(
                    new MissionFinished(), robotId, at);
            e.missionId = m.id();
            e.missionType = m.type();
            e.goalX = m.goalX();
            e.goalY = m.goalY();
            return e;
        }
        MissionFailed e = EdgeEvents.robotEvent(new MissionFailed(),
                robotId, at);
        e.missionId = m.id();
        e.missionType = m.type();
        e.reason = m.reason();
        e.goalX = m.goalX();
        e.goalY = m.goalY();
        return e;
    }
}
