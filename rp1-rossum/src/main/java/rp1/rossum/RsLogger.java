package rp1.rossum;

import java.io.FileWriter;
import java.io.IOException;
import java.io.PrintWriter;
import java.time.LocalTime;
import java.time.format.DateTimeFormatter;
import java.util.ArrayDeque;

/**
 * A client's log: lines {@code LEVEL h:mm:ss.SSS MESSAGE} written to a file and/or standard output,
 * flushed per line. Levels: "s" standard, "v" verbose (dropped unless verbosity is on), "X"
 * important. If the logger thread is started, lines are written from it so that a slow disk never
 * holds up the caller; otherwise they are written at once.
 */
public class RsLogger extends Thread implements RsLogInterface {
    private static final DateTimeFormatter TIME = DateTimeFormatter.ofPattern("h:mm:ss.SSS");

    private final PrintWriter file;
    private final boolean toSystemOut;
    private final ArrayDeque<String> pending = new ArrayDeque<>();
    private boolean verbosity;
    private volatile boolean running;

    /**
     * Logs to {@code fileName} (created or truncated; null for none) and, if {@code toSystemOut},
     * standard output. A file that cannot be opened is reported on standard error and skipped.
     */
    public RsLogger(String fileName, boolean toSystemOut) {
        super("RsLogger");
        setDaemon(true);
        this.file = openOrReport(fileName);
        this.toSystemOut = toSystemOut;
    }

    private static PrintWriter openOrReport(String fileName) {
        if (fileName == null) {
            return null;
        }
        try {
            return open(fileName);
        } catch (IOException e) {
            System.err.println("RsLogger: cannot open log file " + fileName + ": " + e.getMessage());
            return null;
        }
    }

    /** Opens (truncates) a log file, or throws if it cannot be created. */
    static PrintWriter open(String fileName) throws IOException {
        return new PrintWriter(new FileWriter(fileName, false));
    }

    @Override
    public synchronized void logIt(String level, String message) {
        String line = level + " " + LocalTime.now().format(TIME) + " " + message;
        if (running) {
            pending.addLast(line);
            notifyAll();
        } else {
            write(line);
        }
    }

    @Override
    public synchronized void log(String message) {
        LogLevels.standard(this, message);
    }

    @Override
    public void verbose(String message) {
        LogLevels.verbose(this, getVerbosity(), message);
    }

    @Override
    public synchronized boolean getVerbosity() {
        return verbosity;
    }

    @Override
    public synchronized void setVerbosity(boolean value) {
        verbosity = value;
    }

    /** Writes queued lines until {@link #close()}; started with {@link #start()}. */
    @Override
    public void run() {
        synchronized (this) {
            running = true;
        }
        while (true) {
            String line;
            synchronized (this) {
                while (pending.isEmpty() && running) {
                    try {
                        wait();
                    } catch (InterruptedException e) {
                        running = false;
                    }
                }
                if (pending.isEmpty()) {
                    return;
                }
                line = pending.removeFirst();
            }
            write(line);
        }
    }

    /** Writes out any queued lines, stops the logger thread and closes the file. */
    public synchronized void close() {
        running = false;
        while (!pending.isEmpty()) {
            write(pending.removeFirst());
        }
        notifyAll();
        if (file != null) {
            file.close();
        }
    }

    private void write(String line) {
        if (file != null) {
            file.println(line);
            file.flush();
        }
        if (toSystemOut) {
            System.out.println(line);
        }
    }
}
