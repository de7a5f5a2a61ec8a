package eu.brain.iot.bis.impl;

import java.time.Instant;
import java.util.List;
import java.util.Map;

import org.osgi.util.promise.Promise;
import org.osgi.util.promise.TimeoutException;

import eu.brain.iot.bis.api.InstallException;
import eu.brain.iot.bis.api.InstallRequest;
import eu.brain.iot.bis.api.InstalledBehaviour;
import eu.brain.iot.bis.api.InstalledBundle;
import eu.brain.iot.bis.impl.install.Installer;
import eu.brain.iot.bis.impl.repo.BehaviourResource;
import eu.brain.iot.bis.impl.repo.IndexStatus;
import eu.brain.iot.bis.impl.repo.Repositories;

/**
 * Gogo commands {@code bis:list}, {@code bis:install}, {@code bis:uninstall}, {@code bis:stop}, {@code bis:allow},
 * {@code bis:repos}.
 * Every command answers with text, failures included (never a stack trace). Called on the shell's thread; it only
 * waits for the installer's promises.
 */
public final class BisCommands {

    private final Installer installer;
    private final Repositories repositories;
    /** How long a command waits for the installer's answer before it says what the installer is doing. */
    private final long waitMillis;

    BisCommands(Installer installer, Repositories repositories, long waitMillis) {
        this.installer = installer;
        this.repositories = repositories;
        this.waitMillis = waitMillis;
    }

    /** bis:list: the behaviours installed by the installer, when and why; the operator's removals. */
    public String list() {
        StringBuilder out = new StringBuilder();
        List<InstalledBehaviour> installed = installer.installed();
        if (installed.isEmpty()) {
            out.append("no behaviour installed by the Bundle Installer\n");
        }
        for (InstalledBehaviour b : installed) {
            out.append(b.symbolicName).append(' ').append(b.version).append("  ").append(b.state).append("  bundle ")
                    .append(b.bundleId).append("  since ").append(Instant.ofEpochMilli(b.installedAt)).append('\n')
                    .append("    why: ").append(b.reason).append('\n').append("    from: ").append(b.repository)
                    .append('\n').append("    consumes: ").append(String.join(", ", b.consumed)).append('\n');
            installer.lastRestart(b.symbolicName).ifPresent(r -> out.append("    restarted: ")
                    .append(Instant.ofEpochMilli(r.at())).append(" (").append(r.count()).append(r.count() == 1 ? " time"
                            : " times").append(" since the installer started), why: ").append(r.why()).append('\n'));
            for (InstalledBundle d : b.bundles.subList(1, b.bundles.size())) {
                out.append("    needs: ").append(d.symbolicName).append(' ').append(d.version).append(" (bundle ")
                        .append(d.bundleId).append(", used by ").append(d.users).append(")\n");
            }
        }
        installer.pending().forEach(p -> {
            String problem = installer.restoreProblem(p.symbolicName());
            out.append("journal, not back yet: ").append(p.symbolicName()).append(' ').append(p.version())
                    .append(problem == null ? "" : "\n    problem: " + problem).append('\n');
        });
        for (Map.Entry<String, String> e : installer.blocked().entrySet()) {
            out.append("removed or stopped by an operator: ").append(e.getKey()).append(" (").append(e.getValue())
                    .append("); not installed or started automatically until 'bis:allow ").append(e.getKey())
                    .append("' (the next event needing it brings it back) or 'bis:install ").append(e.getKey())
                    .append("' (at once)\n");
        }
        return out.toString();
    }

    /** bis:install NAME|EVENT_TYPE: installs a behaviour by symbolic name, or the best one consuming an event type. */
    public String install(String what) {
        InstallRequest request = new InstallRequest();
        boolean byName = repositories.resources().stream().anyMatch(r -> r.symbolicName().equals(what));
        if (byName) {
            request.symbolicName = what;
        } else {
            request.consumedTypes = List.of(qualify(what));
        }
        request.operator = true;
        request.reason = "bis:install " + what + " by an operator";
        return await(installer.install(request), "installed");
    }

    /**
     * bis:uninstall NAME: uninstalls a behaviour; it is not installed again automatically until allowed. A name that
     * is neither installed, nor in the journal, nor offered by an index is answered as such, and nothing changes.
     */
    public String uninstall(String symbolicName) {
        boolean installed = installer.installed().stream().anyMatch(b -> b.symbolicName.equals(symbolicName))
                || installer.pending().stream().anyMatch(p -> p.symbolicName().equals(symbolicName));
        if (!installed) {
            boolean offered = repositories.resources().stream().anyMatch(r -> r.symbolicName().equals(symbolicName));
            List<String> known = installer.known();
            String what = "nothing is installed under the name " + symbolicName + " (installed: "
                    + (known.isEmpty() ? "none" : String.join(", ", known)) + ")";
            if (!offered) {
                return what + "; no index offers it either: nothing done";
            }
            String answer = await(installer.uninstall(symbolicName, "bis:uninstall by an operator", true), "removed");
            return !answer.startsWith("removed") ? answer : what + "; an index offers it: it is not installed"
                    + " automatically until 'bis:allow " + symbolicName + "' or 'bis:install " + symbolicName + "'";
        }
        String answer = await(installer.uninstall(symbolicName, "bis:uninstall by an operator", true), "uninstalled");
        return answer.startsWith("uninstalled") ? answer + "\nnot installed again automatically until 'bis:allow "
                + symbolicName + "' or 'bis:install " + symbolicName + "'" : answer;
    }

    /**
     * bis:stop NAME: stops a behaviour installed by the installer; unlike Gogo's {@code stop}, which the Behaviour
     * Management Service undoes with the next event the behaviour consumes, it stays stopped until allowed.
     */
    public String stop(String symbolicName) {
        String answer = await(installer.stop(symbolicName, "bis:stop by an operator"), "stopped");
        return answer.startsWith("stopped") ? answer + "\nnot started again automatically until 'bis:allow "
                + symbolicName + "' (the next event it consumes then starts it) or 'bis:install " + symbolicName
                + "' (starts it at once)" : answer;
    }

    /** bis:allow NAME: lifts an operator's removal or stop. */
    public String allow(String symbolicName) {
        try {
            return installer.allowOrFail(symbolicName) ? symbolicName + " may be installed automatically again"
                    : symbolicName + " was not removed by an operator: nothing to allow";
        } catch (InstallException e) {
            return "failed (" + e.problem() + "): " + e.getMessage();
        }
    }

    /** bis:repos: the indexes, when read, their signature state, and the behaviours they offer. */
    public String repos() {
        StringBuilder out = new StringBuilder();
        List<IndexStatus> status = repositories.status();
        if (status.isEmpty()) {
            out.append("no repositories configured (repositories of eu.brain.iot.bis)\n");
        }
        for (IndexStatus s : status) {
            out.append(s.url()).append('\n').append("    ").append(s.resources()).append(" resources, ")
                    .append(s.behaviours()).append(" behaviours; read ")
                    .append(s.readAt() == 0 ? "never" : Instant.ofEpochMilli(s.readAt()).toString())
                    .append(", checked ").append(s.checkedAt() == 0 ? "never" : Instant.ofEpochMilli(s.checkedAt()))
                    .append('\n').append("    signature: ").append(s.signature()).append('\n');
            if (s.lastError() != null) {
                out.append("    problem: ").append(s.lastError()).append('\n');
            }
        }
        for (BehaviourResource r : repositories.resources()) {
            if (r.isBehaviour()) {
                out.append("  ").append(r.symbolicName()).append(' ').append(r.version()).append(" consumes ")
                        .append(r.consumed().size()).append(" types\n");
            }
        }
        return out.toString();
    }

    /** A simple name (e.g. OpenDoorCommand) matched against the consumed types the indexes know. */
    private String qualify(String type) {
        if (type.contains(".")) {
            return type;
        }
        return repositories.resources().stream().flatMap(r -> r.consumed().stream())
                .filter(t -> t.endsWith("." + type)).findFirst().orElse(type);
    }

    private String await(Promise<InstalledBehaviour> promise, String verb) {
        try {
            Throwable failure = promise.timeout(waitMillis).getFailure();
            if (failure instanceof InstallException e) {
                return "failed (" + e.problem() + "): " + e.getMessage();
            }
            if (failure instanceof TimeoutException) {
                List<String> doing = installer.activities();
                return "no answer yet after " + waitMillis / 1000 + " s (shell.wait.ms); the installer goes on"
                        + (doing.isEmpty() ? "" : ", it is " + String.join("; ", doing))
                        + ". 'bis:list' shows when it is done";
            }
            if (failure != null) {
                return "failed: " + eu.brain.iot.bis.impl.repo.Errors.describe(failure);
            }
            InstalledBehaviour b = promise.getValue();
            return verb + " " + b.symbolicName + " " + (b.version == null ? "" : b.version)
                    + (b.bundles.size() > 1 ? " with " + (b.bundles.size() - 1) + " bundles it needs" : "");
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return "interrupted";
        } catch (java.lang.reflect.InvocationTargetException e) {
            return "failed: " + eu.brain.iot.bis.impl.repo.Errors.describe(e.getCause());
        }
    }
}
