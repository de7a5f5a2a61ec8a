package eu.brain.iot.federation.impl;

import java.io.IOException;
import java.nio.file.Path;

/** Creates a fabric key file: {@code java -cp federation.jar eu.brain.iot.federation.impl.KeyGen FILE}. */
public final class KeyGen {

    private KeyGen() {
    }

    public static void main(String[] args) {
        if (args.length != 1) {
            System.err.println("usage: KeyGen FILE   (creates the fabric's signing key; copy FILE to every node)");
            System.exit(2);
        }
        try {
            FabricKey.generate(Path.of(args[0]));
            System.out.println("fabric key written to " + Path.of(args[0]).toAbsolutePath()
                    + "; copy it to every node and set key.file in PID " + FabricConfig.PID);
        } catch (IOException e) {
            System.err.println("fabric key not written: " + e.getMessage());
            System.exit(1);
        }
    }
}
