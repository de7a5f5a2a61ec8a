package org.apache.felix.gogo.shell;

import org.apache.felix.gogo.runtime.CommandSessionImpl;

/** Test double named as the Gogo shell's console loop: its stack frame is what {@code ShellDrain} looks for. */
public final class Console implements Runnable {
    private final CommandSessionImpl session;

    public Console(CommandSessionImpl session) {
        this.session = session;
    }

    @Override
    public void run() {
        session.execute();
    }
}
