package rp1.simulator.batch;

import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

/**
 * Ctrl-C or SIGTERM to a sweep's process, turned into an orderly stop: the JVM's shutdown hook
 * ({@link #signalled()}) runs what was registered to stop the sweep, then waits for the sweep to
 * finish its files and ends the process with the sweep's exit status (130 unless it says otherwise).
 * A sweep that ends by itself leaves through {@link #exit(int)}, which the hook then lets be.
 */
public final class Interruption {
    /** The exit status of an interrupted sweep, as a shell gives a program stopped by Ctrl-C. */
    public static final int STATUS = 130;
    /** How long the hook waits for the sweep to stop its runs and write its files. */
    private static final long FINISH_SECONDS = 120;
    /** What {@link #runAndExit} sets aside, bytes: room for a line or two. */
    private static final int RESERVE_BYTES = 256 << 10;

    private final CountDownLatch handedOver = new CountDownLatch(1);
    private boolean requested;
    private boolean exiting;
    private Runnable onStop = () -> { };
    private volatile int status = STATUS;
    /** Memory set aside for the last line of a sweep that failed for want of it. */
    private byte[] reserve = new byte[RESERVE_BYTES];

    /** A sweep's work, given the interruption that may stop it; answers the exit status. */
    @FunctionalInterface
    public interface Sweeping {
        int run(Interruption interruption);
    }

    /**
     * A sweep's {@code main}: runs it with Ctrl-C and SIGTERM turned into an orderly stop, then ends
     * the process with its status (1 if it failed with a defect or an Error, with a line that says so).
     *
     * @param name  the command, for the message about a defect
     */
    public static void runAndExit(String name, Sweeping sweep) {
        Interruption interruption = new Interruption();
        Runtime.getRuntime().addShutdownHook(new Thread(interruption::signalled, "stop the runs"));
        int status = 1;
        try {
            status = sweep.run(interruption);
        } catch (RuntimeException e) {
            // A defect, not a signal: leave at once rather than let the hook wait for a sweep that is gone.
            System.err.println(name + ": internal error: " + e);
        } catch (Error e) {
            // Out of memory on this thread (a robot filled the heap of a sweep's process): say so
            // rather than end with no word. The runs that finished are in results.csv, and --resume
            // carries out the others.
            interruption.reserve = null;
            System.err.println(name + ": " + e + "; the sweep stops. The runs that finished are kept: add --resume to"
                    + " the same command to carry out the others");
        } finally {
            interruption.exit(status);
        }
    }

    /** Whether the sweep was asked to stop. */
    public synchronized boolean requested() {
        return requested;
    }

    /** What stops the sweep; run at once if it was already asked to stop. */
    public void onStop(Runnable action) {
        boolean now;
        synchronized (this) {
            onStop = action;
            now = requested;
        }
        if (now) {
            action.run();
        }
    }

    /** The shutdown hook: stops the sweep, waits until it has written its files, ends the process. */
    public void signalled() {
        Runnable action;
        synchronized (this) {
            if (exiting) {
                return;
            }
            requested = true;
            action = onStop;
        }
        action.run();
        try {
            handedOver.await(FINISH_SECONDS, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        // The JVM is already shutting down, so System.exit would block: halt with the sweep's status.
        Runtime.getRuntime().halt(status);
    }

    /**
     * Ends the process with {@code status}; after an interruption, hands the status to the shutdown
     * hook, which ends the process with it. Never returns.
     */
    public void exit(int status) {
        boolean leave;
        synchronized (this) {
            leave = !requested;
            exiting = leave;
        }
        if (leave) {
            System.exit(status);
        }
        this.status = status;
        System.out.flush();
        System.err.flush();
        handedOver.countDown();
        while (true) {
            try {
                Thread.sleep(Long.MAX_VALUE);
            } catch (InterruptedException e) {
                // The hook ends the process.
            }
        }
    }
}
