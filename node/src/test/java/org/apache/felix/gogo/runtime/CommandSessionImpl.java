package org.apache.felix.gogo.runtime;

import java.util.concurrent.CountDownLatch;

/** Test double named as the Gogo runtime's session: {@link #execute()} is a command that runs until released. */
public final class CommandSessionImpl {
    public final CountDownLatch entered = new CountDownLatch(1);
    public final CountDownLatch release = new CountDownLatch(1);

    public void execute() {
        entered.countDown();
        try {
            release.await();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
