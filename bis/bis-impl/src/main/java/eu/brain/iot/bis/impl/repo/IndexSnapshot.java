package eu.brain.iot.bis.impl.repo;

import java.net.URI;
import java.util.List;

import org.osgi.resource.Capability;
import org.osgi.resource.Requirement;
import org.osgi.resource.Resource;

import aQute.bnd.osgi.repository.ResourcesRepository;

/**
 * The content of one index as read: its resources (answering requirements through bnd's
 * {@link ResourcesRepository}) and their installer facts. Immutable once built; shared between threads.
 */
public final class IndexSnapshot {

    private final URI location;
    private final ResourcesRepository repository;
    private final List<BehaviourResource> resources;

    IndexSnapshot(URI location, List<Resource> resources) {
        this.location = location;
        this.repository = new ResourcesRepository(resources);
        this.resources = resources.stream().flatMap(r -> BehaviourResource.of(r, location).stream()).toList();
    }

    public URI location() {
        return location;
    }

    public List<BehaviourResource> resources() {
        return resources;
    }

    /** @return the capabilities of this index's resources that satisfy {@code requirement} */
    public List<Capability> providers(Requirement requirement) {
        return repository.findProvider(requirement);
    }

    /** @return the facts of one of this index's resources, or null */
    public BehaviourResource facts(Resource resource) {
        for (BehaviourResource r : resources) {
            if (r.resource() == resource) {
                return r;
            }
        }
        return null;
    }
}
