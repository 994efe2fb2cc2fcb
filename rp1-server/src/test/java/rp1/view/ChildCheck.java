package rp1.view;

import java.util.concurrent.Callable;

/**
 * The frame of a check run by {@link ChildJvm}: prints {@code NAME PASSED} and exits 0 if the check
 * returns, or prints what went wrong, with its stack, and exits 1. Exiting also ends the AWT threads
 * a window leaves behind.
 */
final class ChildCheck {
    private ChildCheck() {
    }

    static void run(String name, Callable<?> check) {
        int status = 1;
        try {
            check.call();
            System.out.println(name + " PASSED");
            status = 0;
        } catch (Throwable t) {
            System.out.println(name + " FAILED: " + t);
            for (Throwable c = t; c != null; c = c.getCause()) {
                System.out.println("caused by " + c);
                for (StackTraceElement e : c.getStackTrace()) {
                    System.out.println("    at " + e);
                }
            }
        }
        System.out.flush();
        System.exit(status);
    }
}
