package eu.brain.iot.bis.impl.repo;

import java.net.URI;
import java.util.List;
import java.util.Map;
import java.util.Optional;

import org.osgi.framework.Version;
import org.osgi.framework.namespace.IdentityNamespace;
import org.osgi.resource.Capability;
import org.osgi.resource.Resource;
import org.osgi.service.repository.ContentNamespace;

import eu.brain.iot.bis.api.BehaviourCandidate;
import eu.brain.iot.eventing.annotation.SmartBehaviourNamespace;

/**
 * What the installer needs to know about one resource of an index: identity, content (URL, SHA-256, size) and, for
 * a behaviour, the event types its {@code eu.brain.iot.behaviour} capabilities consume. Immutable.
 */
public record BehaviourResource(Resource resource, String symbolicName, Version version, URI url, String sha256,
        long size, List<String> consumed, URI repository) {

    /** @return the resource's facts, or empty when it lacks an identity or a content capability */
    public static Optional<BehaviourResource> of(Resource resource, URI repository) {
        Map<String, Object> identity = first(resource, IdentityNamespace.IDENTITY_NAMESPACE);
        Map<String, Object> content = first(resource, ContentNamespace.CONTENT_NAMESPACE);
        if (identity == null || content == null || content.get(ContentNamespace.CAPABILITY_URL_ATTRIBUTE) == null) {
            return Optional.empty();
        }
        Object version = identity.get(IdentityNamespace.CAPABILITY_VERSION_ATTRIBUTE);
        Object size = content.get(ContentNamespace.CAPABILITY_SIZE_ATTRIBUTE);
        List<String> consumed = resource.getCapabilities(SmartBehaviourNamespace.NAMESPACE).stream()
                .flatMap(c -> consumed(c).stream()).distinct().toList();
        return Optional.of(new BehaviourResource(resource,
                String.valueOf(identity.get(IdentityNamespace.IDENTITY_NAMESPACE)),
                version == null ? Version.emptyVersion : Version.parseVersion(version.toString()),
                URI.create(String.valueOf(content.get(ContentNamespace.CAPABILITY_URL_ATTRIBUTE))),
                String.valueOf(content.get(ContentNamespace.CONTENT_NAMESPACE)).toLowerCase(),
                size instanceof Number n ? n.longValue() : -1, consumed, repository));
    }

    public boolean isBehaviour() {
        return !consumed.isEmpty();
    }

    public BehaviourCandidate candidate() {
        BehaviourCandidate candidate = new BehaviourCandidate();
        candidate.symbolicName = symbolicName;
        candidate.version = version.toString();
        candidate.consumed = consumed;
        candidate.repository = repository.toString();
        candidate.url = url.toString();
        candidate.sha256 = sha256;
        candidate.size = size;
        return candidate;
    }

    @Override
    public String toString() {
        return symbolicName + " " + version;
    }

    private static Map<String, Object> first(Resource resource, String namespace) {
        List<Capability> capabilities = resource.getCapabilities(namespace);
        return capabilities.isEmpty() ? null : capabilities.get(0).getAttributes();
    }

    private static List<String> consumed(Capability capability) {
        Object value = capability.getAttributes().get(SmartBehaviourNamespace.CONSUMED);
        if (value instanceof List<?> list) {
            return list.stream().map(String::valueOf).toList();
        }
        return value == null ? List.of() : List.of(String.valueOf(value));
    }
}
