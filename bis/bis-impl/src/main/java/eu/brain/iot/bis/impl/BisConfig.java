package eu.brain.iot.bis.impl;

import org.osgi.service.metatype.annotations.AttributeDefinition;
import org.osgi.service.metatype.annotations.ObjectClassDefinition;

/** Configuration of the Bundle Installer Service (PID {@code eu.brain.iot.bis}); every key is optional. */
@ObjectClassDefinition(name = "BRAIN-IoT Bundle Installer Service", description = "Repositories of behaviour"
        + " bundles, trust, choice and journal of the Bundle Installer")
public @interface BisConfig {

    @AttributeDefinition(description = "URLs of R5 index files (file:, http:, https:; plain or gzipped XML), read in"
            + " this order; bundle URLs in an index are relative to it. Several: an array, or one string of URLs"
            + " separated by commas (as a .cfg file gives it)")
    String[] repositories() default {};

    @AttributeDefinition(description = "Ed25519 public keys an index must be signed with (INDEX.sig beside it): each"
            + " a path to a PEM file (e.g. repository/target/index-signing.pub) or the PEM/base64 text. Empty:"
            + " signatures are not checked")
    String[] trusted_keys() default {};

    @AttributeDefinition(description = "Symbolic names of behaviours to choose first when several consume an"
            + " event type, in order; then the highest version wins")
    String[] prefer() default {};

    @AttributeDefinition(description = "How long an install waits for the behaviour's smart behaviours to be"
            + " registered with the bus after its bundles started (ms)")
    long activation_timeout_ms() default 10_000;

    @AttributeDefinition(description = "The journal's directory (outside the framework's cache and the work tree)."
            + " Empty: <the node's state folder>/bis, the state folder being the framework property fabric.node.state"
            + " or, without it, ${XDG_STATE_HOME or ~/.local/state}/brain-iot/<fabric.node.name>-<hash of"
            + " fabric.node.root>")
    String journal_dir() default "";

    @AttributeDefinition(description = "How often each index is checked for changes (ms; conditional GET over"
            + " HTTP, modification time for files)")
    long refresh_ms() default 10_000;

    @AttributeDefinition(description = "First retry delay when an index is unreachable (ms); doubled at each failure")
    long retry_initial_ms() default 250;

    @AttributeDefinition(description = "Longest retry delay when an index is unreachable (ms)")
    long retry_max_ms() default 30_000;

    @AttributeDefinition(description = "How long a read waits to connect and for the answer's headers (ms)")
    long download_timeout_ms() default 10_000;

    @AttributeDefinition(description = "The longest a whole read may take, headers and body (ms): an index, a"
            + " signature or a bundle that has not arrived completely by then is abandoned, and the error names its URL")
    long download_deadline_ms() default 60_000;

    @AttributeDefinition(description = "The largest index (or its signature) read, in bytes, compressed or not;"
            + " a longer one is refused")
    long index_max_bytes() default 16L * 1024 * 1024;

    @AttributeDefinition(description = "The largest bundle downloaded when its index states no size (bytes); a"
            + " bundle whose index states a size is read up to that size and no further")
    long bundle_max_bytes() default 256L * 1024 * 1024;

    @AttributeDefinition(description = "How many bundle downloads run at once; a slow download holds up only its"
            + " own install")
    int download_threads() default 4;

    @AttributeDefinition(description = "How long the shell's bis:install, bis:uninstall and bis:stop wait for the"
            + " answer (ms); the work goes on after, and the command says what it is doing")
    long shell_wait_ms() default 30_000;

    @AttributeDefinition(description = "At start, how long the journal's behaviours may take to come back before"
            + " the installer is offered as a service anyway (ms); those not back by then keep being retried")
    long restore_timeout_ms() default 30_000;
}
