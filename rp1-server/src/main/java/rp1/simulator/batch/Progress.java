package rp1.simulator.batch;

import java.io.PrintStream;
import java.util.Locale;

/**
 * Tells the user how a sweep is going. On a terminal, one line redrawn in place: a bar, the runs done
 * and failed, and an estimate of the time left. Elsewhere (a CI log, a pipe), a plain line per run.
 */
public final class Progress {
    private static final int BAR = 30;

    private final int total;
    private final PrintStream out;
    private final boolean terminal;
    private final long start = System.nanoTime();
    private int done;
    private int failed;

    /**
     * @param total    the number of runs
     * @param terminal whether {@code out} is a terminal (draw the bar) or not (print lines)
     */
    public Progress(int total, PrintStream out, boolean terminal) {
        this.total = total;
        this.out = out;
        this.terminal = terminal;
    }

    /** A run has ended. Any thread. */
    public synchronized void finished(Batch.Outcome o) {
        done++;
        if (!o.report().succeeded()) {
            failed++;
        }
        if (terminal) {
            out.print("\r" + bar());
        } else {
            // Put together by hand: a format string is parsed and interpreted anew for every run.
            out.println("[" + done + "/" + total + "] seed " + o.run().seed() + " on " + o.run().plan()
                    + configuration(o.run()) + ": " + o.report().endReason() + " (" + elapsed(o.wallSeconds()) + ")");
        }
        out.flush();
    }

    /** Every run has ended. */
    public synchronized void close() {
        if (terminal) {
            out.println();
        }
    }

    /**
     * Wall seconds (not negative) as a reader wants them: below a second in whole milliseconds (a bumper
     * run takes a few, which tenths of a second showed as "0.0 s"), else to the nearest tenth of a second.
     */
    static String elapsed(double seconds) {
        long millis = Math.round(seconds * 1000.0);
        if (millis < 1000) {
            return millis + " ms";
        }
        long t = Math.round(seconds * 10.0);
        return (t / 10) + "." + (t % 10) + " s";
    }

    private String bar() {
        int filled = total == 0 ? BAR : done * BAR / total;
        double elapsed = (System.nanoTime() - start) * 1e-9;
        String left = done == 0 ? "" : String.format(Locale.ROOT, ", about %s left",
                duration(elapsed / done * (total - done)));
        return "[" + "#".repeat(filled) + ".".repeat(BAR - filled) + "] " + done + "/" + total + " runs, "
                + failed + " failed" + left + "   ";
    }

    private static String duration(double seconds) {
        long s = Math.round(seconds);
        return s >= 60 ? (s / 60) + " min " + (s % 60) + " s" : s + " s";
    }

    /** The varied keys' values of a run, as " with K=V ..."; empty when nothing varies. */
    private static String configuration(Batch.Run run) {
        StringBuilder b = new StringBuilder();
        run.configuration().forEach((k, v) -> b.append(b.length() == 0 ? " with " : " ").append(k).append('=').append(v));
        return b.toString();
    }
}
