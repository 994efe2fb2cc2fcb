package rp1.simulator.launch;

import java.security.CodeSource;
import java.util.Map;
import java.util.Optional;

/**
 * Who made the process exit, asked from a shutdown hook: a robot loaded into the process that called
 * {@code System.exit} (or {@code Runtime.exit}) ends the process as Ctrl-C would, and without this the
 * run would be stopped as if the user had asked, and count as one that went as asked.
 */
public final class ExitCaller {
    private ExitCaller() {
    }

    /**
     * Where code outside the simulator called {@code System.exit} or {@code Runtime.exit} on a thread
     * still in that call, as "CLASS.METHOD(FILE:LINE)"; empty if none did (the process was signalled,
     * or the simulator itself is exiting).
     */
    public static Optional<String> outsideTheSimulator() {
        for (Map.Entry<Thread, StackTraceElement[]> e : Thread.getAllStackTraces().entrySet()) {
            Optional<String> caller = callerOfExit(e.getValue());
            if (caller.isPresent()) {
                return caller;
            }
        }
        return Optional.empty();
    }

    /** In one thread's stack, the frame that called exit if it is not the simulator's own. */
    static Optional<String> callerOfExit(StackTraceElement[] stack) {
        for (int i = 0; i + 1 < stack.length; i++) {
            if (isExit(stack[i]) && !isExit(stack[i + 1])) {
                StackTraceElement caller = stack[i + 1];
                return isTheSimulators(caller.getClassName()) ? Optional.empty() : Optional.of(shown(caller));
            }
        }
        return Optional.empty();
    }

    /**
     * Whether the class is the simulator's own: one that comes from where this class came from (a
     * robot's classes come from its own jars or folders, and may be in any package).
     */
    private static boolean isTheSimulators(String className) {
        try {
            Class<?> c = Class.forName(className, false, ExitCaller.class.getClassLoader());
            CodeSource ours = ExitCaller.class.getProtectionDomain().getCodeSource();
            CodeSource its = c.getProtectionDomain().getCodeSource();
            return ours != null && its != null && ours.getLocation().equals(its.getLocation());
        } catch (ClassNotFoundException | LinkageError | SecurityException e) {
            return false;
        }
    }

    /** "CLASS.METHOD(FILE:LINE)": a frame as a log line names it, without its module or class loader. */
    static String shown(StackTraceElement frame) {
        return frame.getClassName() + "." + frame.getMethodName() + "(" + frame.getFileName() + ":"
                + frame.getLineNumber() + ")";
    }

    /** Whether a thread with this stack is in {@code System.exit} (waiting for the shutdown hooks). */
    static boolean isExiting(StackTraceElement[] stack) {
        for (StackTraceElement f : stack) {
            if (isExit(f)) {
                return true;
            }
        }
        return false;
    }

    private static boolean isExit(StackTraceElement f) {
        return f.getMethodName().equals("exit")
                && (f.getClassName().equals("java.lang.Runtime") || f.getClassName().equals("java.lang.System"));
    }
}
