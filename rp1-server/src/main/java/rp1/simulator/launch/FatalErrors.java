package rp1.simulator.launch;

import java.io.PrintStream;

/**
 * Ends the server process when an {@code Error} escapes any of its threads. Without it such a thread
 * (the network thread, the task thread, after an OutOfMemoryError) dies alone and the process lingers,
 * listening and serving nobody. The message goes to standard error; the process then stops as on
 * Ctrl-C (clients closed, log and recording flushed), or is halted if that does not finish within
 * {@value #STOP_MILLIS} ms, with {@link ExitStatus#FATAL_ERROR}. Exceptions that are not errors
 * keep the JVM's default treatment: where they matter, the threads catch them themselves.
 */
final class FatalErrors implements Thread.UncaughtExceptionHandler {
    static final long STOP_MILLIS = 5000;

    private final Thread.UncaughtExceptionHandler otherwise;
    private final PrintStream err;
    /** Memory set aside while all is well, given back so that the message can be written when it is not. */
    private volatile byte[] reserve = new byte[1 << 20];

    private FatalErrors(Thread.UncaughtExceptionHandler otherwise, PrintStream err) {
        this.otherwise = otherwise;
        this.err = err;
    }

    /** Makes every thread of this process end the process on an {@code Error}. */
    static void install() {
        Thread.setDefaultUncaughtExceptionHandler(new FatalErrors(Thread.getDefaultUncaughtExceptionHandler(), System.err));
    }

    @Override
    public void uncaughtException(Thread t, Throwable e) {
        if (!(e instanceof Error)) {
            if (otherwise != null) {
                otherwise.uncaughtException(t, e);
            } else {
                t.getThreadGroup().uncaughtException(t, e);
            }
            return;
        }
        reserve = null;
        try {
            err.println("rp1.Server: " + e + " on thread \"" + t.getName() + "\"; the server stops (exit status "
                    + ExitStatus.FATAL_ERROR + ")");
            err.flush();
            Thread stop = new Thread(() -> System.exit(ExitStatus.FATAL_ERROR), "fatal error exit");
            stop.setDaemon(true);
            stop.start();
            stop.join(STOP_MILLIS);
        } catch (Throwable ignored) {
            // Out of memory even for this: halting below is all that is left.
        } finally {
            Runtime.getRuntime().halt(ExitStatus.FATAL_ERROR);
        }
    }
}
