package eu.brain.iot.scenario;

import java.util.List;

/** The judge's findings: each check with whether it passed and what was seen. Immutable. */
public record Verdict(List<Check> checks) {

    /** One requirement checked on the ground truth. */
    public record Check(String name, boolean passed, String detail) {
    }

    public boolean passed() {
        return checks.stream().allMatch(Check::passed);
    }

    public List<Check> failed() {
        return checks.stream().filter(c -> !c.passed()).toList();
    }
}
