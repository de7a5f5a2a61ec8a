package eu.brain.iot.bip.generate;

import eu.brain.iot.bip.Models;

/** Test helpers: the language's test models, loaded and checked, ready to generate. */
final class Tools {

    private Tools() {
    }

    /** Parses and checks in-memory sources (file name, text, file name, text, ...). */
    static Toolchain check(String... namesAndTexts) {
        return Toolchain.of(Models.check(namesAndTexts));
    }

    /** The warehouse system (all four behaviour models) as the run's own packages, checked. */
    static Toolchain warehouse() {
        return Toolchain.of(Models.warehouse());
    }
}
