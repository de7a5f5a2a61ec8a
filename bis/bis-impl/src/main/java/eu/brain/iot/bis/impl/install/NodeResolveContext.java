package eu.brain.iot.bis.impl.install;

import java.util.ArrayList;
import java.util.Collection;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.osgi.framework.Version;
import org.osgi.framework.namespace.IdentityNamespace;
import org.osgi.framework.wiring.BundleRevision;
import org.osgi.framework.wiring.FrameworkWiring;
import org.osgi.resource.Capability;
import org.osgi.resource.Namespace;
import org.osgi.resource.Requirement;
import org.osgi.resource.Resource;
import org.osgi.resource.Wiring;
import org.osgi.service.resolver.HostedCapability;
import org.osgi.service.resolver.ResolveContext;

import eu.brain.iot.bis.impl.repo.Repositories;

/**
 * What the OSGi Resolver resolves a behaviour against: the framework's bundles (their wirings, and their
 * capabilities through {@link FrameworkWiring#findProviders}) first, then the repositories' resources, leaving out
 * a repository resource whose identity (symbolic name and version) the framework already holds. Built and used on
 * the installer's thread for one resolution.
 */
final class NodeResolveContext extends ResolveContext {

    private final BundleContext context;
    private final Resource mandatory;
    private final Repositories repositories;
    private final Set<String> installedIdentities = new HashSet<>();
    private final Map<Resource, Wiring> wirings = new HashMap<>();

    NodeResolveContext(BundleContext context, Resource mandatory, Repositories repositories) {
        this.context = context;
        this.mandatory = mandatory;
        this.repositories = repositories;
        for (Bundle bundle : context.getBundles()) {
            BundleRevision revision = bundle.adapt(BundleRevision.class);
            if (revision == null) {
                continue;
            }
            installedIdentities.add(bundle.getSymbolicName() + ";" + bundle.getVersion());
            if (revision.getWiring() != null) {
                wirings.put(revision, revision.getWiring());
            }
        }
    }

    @Override
    public Collection<Resource> getMandatoryResources() {
        return List.of(mandatory);
    }

    @Override
    public List<Capability> findProviders(Requirement requirement) {
        List<Capability> providers = new ArrayList<>();
        FrameworkWiring framework = context.getBundle(0).adapt(FrameworkWiring.class);
        for (Capability capability : framework.findProviders(requirement)) {
            if (capability.getResource() instanceof BundleRevision revision
                    && revision.getBundle().getState() != Bundle.UNINSTALLED) {
                providers.add(capability);
            }
        }
        for (Capability capability : repositories.providers(requirement)) {
            if (capability.getResource() == mandatory || !installedIdentities.contains(identity(capability))) {
                providers.add(capability);
            }
        }
        return providers;
    }

    @Override
    public int insertHostedCapability(List<Capability> capabilities, HostedCapability hostedCapability) {
        capabilities.add(hostedCapability);
        return capabilities.size() - 1;
    }

    @Override
    public boolean isEffective(Requirement requirement) {
        String effective = requirement.getDirectives().get(Namespace.REQUIREMENT_EFFECTIVE_DIRECTIVE);
        return effective == null || Namespace.EFFECTIVE_RESOLVE.equals(effective);
    }

    @Override
    public Map<Resource, Wiring> getWirings() {
        return wirings;
    }

    private static String identity(Capability capability) {
        for (Capability id : capability.getResource().getCapabilities(IdentityNamespace.IDENTITY_NAMESPACE)) {
            Object version = id.getAttributes().get(IdentityNamespace.CAPABILITY_VERSION_ATTRIBUTE);
            return id.getAttributes().get(IdentityNamespace.IDENTITY_NAMESPACE) + ";"
                    + (version == null ? Version.emptyVersion : Version.parseVersion(version.toString()));
        }
        return "";
    }
}
