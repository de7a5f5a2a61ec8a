package eu.brain.iot.edge.impl;

import java.net.URI;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Executor;

/**
 * Announces each mission's end once. A robot's answer shows its running mission, else the next queued, else the
 * last ended, so an end is usually seen in a poll; but a mission can end and the next one start between two
 * polls. Then the robot's history ({@code query_state}) is asked for the mission that vanished.
 * Called on the fleet thread; history answers are brought back to it.
 */
final class MissionTracker {

    private final AnswerParser parser;
    private final Outbox events;
    private final EdgeLog log;

    MissionTracker(AnswerParser parser, Outbox events, EdgeLog log) {
        this.parser = parser;
        this.events = events;
        this.log = log;
    }

    void track(PolledDevice d, RobotAnswer before, RobotAnswer now, FleetHttpClient client, URI base,
            Executor fleet, Instant at) {
        RobotAnswer.Mission current = now.mission();
        if (before == null) {
            if (current != null && current.ended()) {
                d.firstReport(current.id()); // ended before the edge was watching: not news
            }
            return;
        }
        RobotAnswer.Mission earlier = before.mission();
        if (earlier != null && !earlier.ended() && (current == null || current.id() != earlier.id())
                && d.heldEnds == null) {
            d.heldEnds = new ArrayList<>();
            askHistory(d, earlier, client, base, fleet);
        }
        if (current != null && current.ended()) {
            if (d.heldEnds != null) {
                if (!d.heldEnds.contains(current)) {
                    d.heldEnds.add(current);
                }
            } else if (d.firstReport(current.id())) {
                events.publish(ChangeDetector.missionEnded(d.id, current, at));
            }
        }
    }

    private void askHistory(PolledDevice d, RobotAnswer.Mission vanished, FleetHttpClient client, URI base,
            Executor fleet) {
        String component = switch (vanished.type()) {
            case "pick" -> "PickComponent";
            case "place" -> "PlaceComponent";
            default -> "GoToComponent";
        };
        client.get(FleetPoller.component(base, d.id, component, "query_state")).whenComplete((answer, error) -> {
            RobotAnswer.Mission found = null;
            String problem = null;
            if (error != null || !answer.ok()) {
                problem = error != null ? error.getMessage() : "HTTP " + answer.status();
            } else {
                try {
                    for (RobotAnswer.Mission m : parser.history(d.id, answer.body())) {
                        if (m.id() == vanished.id() && m.ended()) {
                            found = m;
                        }
                    }
                } catch (DeviceIOException e) {
                    problem = e.getMessage();
                }
            }
            RobotAnswer.Mission ended = found;
            String why = problem;
            fleet.execute(() -> historyAnswered(d, vanished, ended, why));
        });
    }

    /** On the fleet thread: announce the vanished mission's end, then the ends held back meanwhile. */
    private void historyAnswered(PolledDevice d, RobotAnswer.Mission vanished, RobotAnswer.Mission ended,
            String problem) {
        List<RobotAnswer.Mission> held = d.heldEnds;
        d.heldEnds = null;
        if (d.removed) {
            return;
        }
        if (ended != null && d.firstReport(ended.id())) {
            events.publish(ChangeDetector.missionEnded(d.id, ended, Instant.now()));
        } else if (ended == null) {
            log.debug("could not learn how mission " + vanished.id() + " of " + d.id + " ended: "
                    + (problem != null ? problem : "not in its history"));
        }
        for (RobotAnswer.Mission m : held) {
            if (d.firstReport(m.id())) {
                events.publish(ChangeDetector.missionEnded(d.id, m, Instant.now()));
            }
        }
    }
}
