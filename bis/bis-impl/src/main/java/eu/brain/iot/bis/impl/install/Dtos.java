package eu.brain.iot.bis.impl.install;

import java.util.ArrayList;
import java.util.List;

import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;

import eu.brain.iot.bis.api.InstalledBehaviour;
import eu.brain.iot.bis.api.InstalledBundle;
import eu.brain.iot.bis.impl.journal.BehaviourRecord;
import eu.brain.iot.bis.impl.journal.BundleFact;

/** Turns ledger records into the API's DTOs, with the bundles' states now. Stateless. */
final class Dtos {

    private Dtos() {
    }

    static InstalledBehaviour behaviour(BehaviourRecord r, BundleContext context, Ledger ledger) {
        InstalledBehaviour dto = new InstalledBehaviour();
        dto.symbolicName = r.symbolicName();
        dto.version = r.version();
        dto.consumed = r.consumed();
        dto.repository = r.repository();
        dto.installedAt = r.installedAt();
        dto.reason = r.reason();
        Bundle own = context.getBundle(r.own().location());
        dto.bundleId = own == null ? -1 : own.getBundleId();
        dto.state = state(own);
        List<InstalledBundle> bundles = new ArrayList<>();
        for (BundleFact f : r.bundles()) {
            InstalledBundle b = new InstalledBundle();
            Bundle bundle = context.getBundle(f.location());
            b.symbolicName = f.symbolicName();
            b.version = f.version();
            b.sha256 = f.sha256();
            b.bundleId = bundle == null ? -1 : bundle.getBundleId();
            b.users = ledger.otherUsers(f.location(), r.symbolicName()) + 1;
            bundles.add(b);
        }
        dto.bundles = bundles;
        return dto;
    }

    static String state(Bundle bundle) {
        if (bundle == null) {
            return "UNINSTALLED";
        }
        return switch (bundle.getState()) {
        case Bundle.ACTIVE -> "ACTIVE";
        case Bundle.STARTING -> "STARTING";
        case Bundle.STOPPING -> "STOPPING";
        case Bundle.RESOLVED -> "RESOLVED";
        case Bundle.INSTALLED -> "INSTALLED";
        default -> "UNINSTALLED";
        };
    }
}
