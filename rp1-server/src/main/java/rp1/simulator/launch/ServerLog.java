package rp1.simulator.launch;

import java.io.FileWriter;
import java.io.IOException;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.time.Clock;
import java.time.LocalTime;
import java.util.function.DoubleSupplier;

import rp1.rossum.RsLogAdapter;

/**
 * The server's log (behavior.md section 3.9): lines {@code LEVEL h:mm:ss.SSS SSSS.mmm: MESSAGE}, where
 * the second field is the wall clock (12-hour, no AM/PM) and the third the simulation time modulo
 * 10000 s. Lines go to a file (flushed per line, so a crash loses nothing) and/or standard output.
 * Levels: "X" important, "s" standard, "v" verbose (written only when verbosity is on).
 *
 * <p>When neither target is on, the server's own important lines ({@link #important}) still go to
 * standard error: a server that stops because a client failed must say why somewhere. Loaded clients
 * log into this log too ({@code dlcSetLog}).
 */
public final class ServerLog extends RsLogAdapter {
    private final PrintWriter file;
    private final PrintStream standardOutput;
    private final PrintStream standardError;
    private volatile DoubleSupplier simTime = () -> 0.0;
    /**
     * The wall clock in the time zone the log was opened in: {@link LocalTime#now()} looks the default
     * zone up for every line, which was more than half of writing a line in a sweep's runs.
     */
    private final Clock wallClock = Clock.systemDefaultZone();
    private boolean closed;

    private ServerLog(PrintWriter file, PrintStream standardOutput, PrintStream standardError, boolean verbose) {
        this.file = file;
        this.standardOutput = standardOutput;
        this.standardError = standardError;
        setVerbosity(verbose);
    }

    /**
     * Opens a log.
     *
     * @param fileName  the log file, created or truncated; null for none
     * @param toSystemOut whether lines also go to standard output
     * @param verbose   whether "v" lines are written
     * @throws IOException if the file cannot be created
     */
    public static ServerLog open(String fileName, boolean toSystemOut, boolean verbose) throws IOException {
        PrintWriter file = fileName == null ? null : new PrintWriter(new FileWriter(fileName, false));
        return new ServerLog(file, toSystemOut ? System.out : null, System.err, verbose);
    }

    /** Where the simulation time in each line comes from (0 until the simulation exists). */
    public void setSimTime(DoubleSupplier source) {
        simTime = source;
    }

    /** Formats one line; {@code simTime} is reduced modulo 10000 s and truncated to milliseconds. */
    static String format(String level, LocalTime wallClock, double simTime, String message) {
        long millis = (long) Math.floor(simTime * 1000.0) % 10_000_000L;
        if (millis < 0) {
            millis += 10_000_000L;
        }
        // As String.format("%s %s %04d.%03d: %s", ...) would, without parsing a format for every line.
        StringBuilder line = new StringBuilder(32 + message.length()).append(level).append(' ');
        clock(line, wallClock).append(' ');
        padded(line, millis / 1000, 4).append('.');
        return padded(line, millis % 1000, 3).append(": ").append(message).toString();
    }

    /**
     * Appends the wall clock as {@code h:mm:ss.SSS} (the hour of a twelve-hour clock, 1 to 12) would
     * format it: a server writes a line per event or two, and a formatter pattern interpreted for each
     * was a run's largest cost in the log.
     */
    static StringBuilder clock(StringBuilder line, LocalTime time) {
        int hour = time.getHour() % 12;
        line.append(hour == 0 ? 12 : hour).append(':');
        padded(line, time.getMinute(), 2).append(':');
        padded(line, time.getSecond(), 2).append('.');
        return padded(line, time.getNano() / 1_000_000, 3);
    }

    /** Appends {@code value} (not negative) with zeros in front to {@code digits} digits. */
    private static StringBuilder padded(StringBuilder line, long value, int digits) {
        long below = 10;
        for (int i = 1; i < digits; i++, below *= 10) {
            if (value < below) {
                line.append('0');
            }
        }
        return line.append(value);
    }

    /**
     * Writes a line. The simulation time is read before the log's lock is taken (it needs the
     * scheduler's); the wall clock after, so that lines appear in wall-clock order.
     */
    @Override
    public void logIt(String level, String message) {
        line(level, message, false);
    }

    private void line(String level, String message, boolean important) {
        double t = simTime.getAsDouble();
        synchronized (this) {
            write(format(level, LocalTime.now(wallClock), t, message), important);
        }
    }

    /** Writes a line exactly as given (the memory figures at shutdown have no level or time). */
    public synchronized void raw(String line) {
        write(line, false);
    }

    private void write(String line, boolean important) {
        if (closed) {
            return;
        }
        if (file != null) {
            file.println(line);
            file.flush();
        }
        if (standardOutput != null) {
            standardOutput.println(line);
        } else if (important && file == null) {
            standardError.println(line);
        }
    }

    /** Writes one of the server's important ("X") lines; on standard error if there is no other target. */
    public void important(String message) {
        line("X", message, true);
    }

    /** Flushes and closes the file; later lines are dropped. */
    public synchronized void close() {
        closed = true;
        if (file != null) {
            file.close();
        }
        if (standardOutput != null) {
            standardOutput.flush();
        }
    }
}
