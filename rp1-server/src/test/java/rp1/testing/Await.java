package rp1.testing;

import java.time.Duration;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;

import org.opentest4j.AssertionFailedError;

/**
 * Waiting in tests for something another thread does. Every wait fails the test at its deadline
 * with the message given, so a condition that never comes true cannot fall through to an assertion
 * that happens to hold anyway. Interruption fails the test too. No checked exceptions: usable inside
 * tasks and handlers.
 */
public final class Await {
    private static final long POLL_NANOS = TimeUnit.MILLISECONDS.toNanos(1);

    private Await() {
    }

    /** Returns once {@code condition} holds; fails with {@code message} if it does not within {@code timeout}. */
    public static void await(BooleanSupplier condition, Duration timeout, String message) {
        long deadline = System.nanoTime() + timeout.toNanos();
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() - deadline > 0) {
                throw new AssertionFailedError(message + " (not within " + describe(timeout) + ")");
            }
            pause(POLL_NANOS);
        }
    }

    /** Returns once {@code latch} is at zero; fails with {@code message} if it is not within {@code timeout}. */
    public static void await(CountDownLatch latch, Duration timeout, String message) {
        try {
            if (!latch.await(timeout.toNanos(), TimeUnit.NANOSECONDS)) {
                throw new AssertionFailedError(message + " (not within " + describe(timeout) + ")");
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new AssertionFailedError(message + " (interrupted while waiting)", e);
        }
    }

    /**
     * Lets at least {@code duration} of wall time pass on this thread. Only for checks that do not
     * depend on another thread having been scheduled meanwhile: that a paced clock, which reads the
     * wall clock itself, did not move.
     */
    public static void letWallTimePass(Duration duration) {
        long end = System.nanoTime() + duration.toNanos();
        for (long left = duration.toNanos(); left > 0; left = end - System.nanoTime()) {
            pause(left);
        }
    }

    private static void pause(long nanos) {
        try {
            TimeUnit.NANOSECONDS.sleep(nanos);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new AssertionFailedError("interrupted while waiting", e);
        }
    }

    private static String describe(Duration d) {
        return d.toMillis() + " ms";
    }
}
