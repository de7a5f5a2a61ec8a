package eu.brain.iot.edge.rest.api;

import org.osgi.annotation.versioning.ProviderType;

import jakarta.servlet.http.HttpServletRequest;

/**
 * The gate of the edge's REST API, offered to the node's other web parts: a whiteboard filter of theirs asks it
 * about each request and answers the {@link Refusal} as a JSON error itself. One gate for the whole node: the same
 * accepted host names (configuration {@code allowed.hosts}), the same token and the same sessions, whose cookie's
 * path covers every part of the node.
 * <p>
 * Thread-safe: called from any container thread.
 */
@ProviderType
public interface AccessGate {

    /** Where a browser opens a session: POST with {@code Authorization: Bearer <token>} and a JSON body. */
    String SESSION_PATH = "/sensinact/session";

    /**
     * Checks a request, in order: {@code Host} names this server (else 421), {@code Origin} is absent or this
     * server (403), with {@code authenticate} and the node exposed (or configured with {@code auth=token}): a valid
     * bearer token or session cookie (401). Methods and content types are the caller's to check (a read-only part
     * answers 405 to a POST; one that accepts a POST must demand {@code Content-Type: application/json}, as
     * {@code /sensinact} does, so that no page of another site can send it without a preflight).
     *
     * @param request the request, before it reaches a servlet
     * @param authenticate whether this resource needs authentication when the node requires it; {@code false} for
     *        what holds no data (a page's static files, which must load to show a login form)
     * @return {@code null} when the request may go on, else why not
     */
    Refusal check(HttpServletRequest request, boolean authenticate);

    /**
     * Why a request is refused.
     *
     * @param status the HTTP status to answer (401, 403, 421; 503 while the gate cannot read its token)
     * @param field the header at fault ({@code Host}, {@code Origin}, {@code Authorization}),
     *        or {@code null}
     * @param message what was wrong and what to do, for the caller
     */
    record Refusal(int status, String field, String message) {
    }
}
