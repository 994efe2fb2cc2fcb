package rp1;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.Locale;

import rp1.io.IoFailures;
import rp1.io.WholeFiles;
import rp1.rossum.RsLogAdapter;
import rp1.rossum.RsLogInterface;
import rp1.simulator.config.Suggestion;
import rp1.simulator.outcome.RunStatistics;
import rp1.simulator.record.Recording;
import rp1.simulator.record.RecordingException;
import rp1.simulator.record.RecordingReader;
import rp1.simulator.record.Replayer;
import rp1.simulator.snapshot.WorldSnapshot;
import rp1.view.Pictures;
import rp1.view.Renderer;
import rp1.web.ReplayPage;
import rp1.web.RunTrace;

/**
 * Replays a recorded run without its clients (docs/recording.md):
 * {@code java rp1.Replay FILE [--events OUT] [--snapshot OUT.png] [--html OUT.html] [--until T]}. The
 * event log it writes is the one the run wrote, byte for byte, the picture the one the run left, and
 * the page plays the run in a browser. Exit status 0
 * when replayed, 1 when the recording cannot be replayed or what the replay writes cannot be written
 * (the message says why), 3 when the replay reached the end of the run but sent other events than the
 * run did, 4 when the recording is partial (the run was killed) and was replayed as far as it goes.
 */
public final class Replay {
    /** Exit status when the replay's events differ from the run's. */
    public static final int DIFFERS = 3;
    /** Exit status when the recording has no end (the run did not stop cleanly) and was replayed as far as it goes. */
    public static final int PARTIAL = 4;

    /** The command that starts a replay through this class directly, as its usage names it. */
    private static final String DIRECT = "java rp1.Replay";
    /** The options, after the usage's first line. */
    private static final String OPTIONS = String.join("\n",
            "  RECORDING        a file written by the server with recordFileName",
            "  --events OUT     write every event sent, one line each, as eventLogFileName does",
            "  --snapshot PNG   write a picture of the world where the replay stops",
            "  --html PAGE      write a page that plays the run in a browser (one self-contained file)",
            "  --until T        stop at simulated time T (seconds) instead of the end of the run",
            "  -h, --help       print this and exit");

    private Replay() {
    }

    /** Replays; the process exits with the status. */
    public static void main(String[] args) {
        main(DIRECT, args);
    }

    /** {@link #main(String[])} for a replay started as {@code command} ({@code rp1 replay}), which its usage names. */
    public static void main(String command, String[] args) {
        System.exit(run(command, args, System.out, System.err));
    }

    /** What the command line may hold, for a replay started as {@code command}. */
    static String usage(String command) {
        return "usage: " + command + " RECORDING [--events OUT] [--snapshot OUT.png] [--html OUT.html] [--until T]\n"
                + OPTIONS;
    }

    /** Replays as the command line asks; returns the exit status. */
    public static int run(String[] args, PrintStream out, PrintStream err) {
        return run(DIRECT, args, out, err);
    }

    /** {@link #run(String[], PrintStream, PrintStream)} for a replay started as {@code command}. */
    static int run(String command, String[] args, PrintStream out, PrintStream err) {
        String usage = usage(command);
        Options o;
        try {
            o = Options.parse(args);
        } catch (IllegalArgumentException e) {
            err.println("rp1.Replay: " + e.getMessage() + "\n" + usage);
            return 1;
        }
        if (o == null) {
            out.println(usage);
            return 0;
        }
        try {
            Recording recording = RecordingReader.read(existing(o.recording));
            if (recording.tornLine() > 0) {
                err.println("rp1.Replay: " + o.recording + ":" + recording.tornLine() + ": the last line was cut off"
                        + " while it was being written (the run was killed); it is left out");
            }
            Replayer replayer;
            try {
                replayer = Replayer.prepare(recording, o.events, log(err));
            } catch (IOException e) {
                err.println("rp1.Replay: cannot write the event log " + o.events + ": " + IoFailures.why(e));
                return 1;
            }
            RunStatistics paths = RunStatistics.watch(replayer.simulation());
            RunTrace trace = o.html == null ? null : RunTrace.attach(replayer.simulation());
            Replayer.Outcome outcome = replayer.run(o.until);
            if (replayer.eventLogFailure() != null) {
                err.println("rp1.Replay: " + replayer.eventLogFailure());
                return 1;
            }
            if (o.snapshot != null) {
                Renderer renderer = new Renderer(replayer.simulation().getWorld().getPlan());
                WorldSnapshot snapshot = WorldSnapshot.of(replayer.simulation().getWorld(), outcome.time());
                if (!written("picture", o.snapshot, err,
                        () -> Pictures.writePng(Pictures.renderCaptioned(renderer, snapshot, paths.trails()), o.snapshot))) {
                    return 1;
                }
            }
            if (trace != null && !written("page", o.html, err,
                    () -> ReplayPage.write(trace, o.recording.getFileName().toString(), outcome.time(), o.html))) {
                return 1;
            }
            return report(recording, outcome, o, out, err);
        } catch (RecordingException e) {
            err.println("rp1.Replay: " + e.getMessage());
            return 1;
        }
    }

    /** Writes an output. */
    @FunctionalInterface
    private interface Output {
        void write() throws IOException;
    }

    /** Writes {@code file}, the replay's {@code what}; false, with why told on {@code err}, if it could not be. */
    private static boolean written(String what, Path file, PrintStream err, Output output) {
        try {
            output.write();
            return true;
        } catch (IOException e) {
            err.println("rp1.Replay: cannot write the " + what + " " + file + ": " + IoFailures.why(e));
            return false;
        }
    }

    /**
     * The recording, which must exist; the {@code .part} a killed run leaves beside a missing one is
     * named, so the user knows where its remains are.
     */
    private static Path existing(Path recording) throws RecordingException {
        Path part = WholeFiles.partOf(recording);
        if (Files.notExists(recording) && Files.exists(part)) {
            throw new RecordingException(recording + " does not exist, but " + part + " does: the run did not stop"
                    + " cleanly; replay what it left with: rp1.Replay " + part);
        }
        return recording;
    }

    private static int report(Recording recording, Replayer.Outcome outcome, Options o, PrintStream out, PrintStream err) {
        String figures = String.format(Locale.ROOT, "%d tasks, %d events, to simulated time %s s",
                outcome.tasks(), outcome.events(), outcome.time());
        if (outcome.matches()) {
            out.println("Replayed " + o.recording + ": " + figures + "; the events are those of the recorded run");
            return 0;
        }
        if (outcome.difference() != null) {
            err.println("rp1.Replay: " + o.recording + ": the replay differs from the recorded run: " + outcome.difference()
                    + " (" + figures + ")");
            return DIFFERS;
        }
        if (outcome.partial()) {
            err.println("rp1.Replay: partial recording: " + o.recording + " ends at t=" + outcome.time() + " s (it has"
                    + " no end line: the run did not stop cleanly); replayed as far as it goes: " + figures);
            return PARTIAL;
        }
        out.println("Replayed " + o.recording + " up to " + o.until + " s: " + figures);
        return 0;
    }

    /** Important lines of the replayed simulation (a task that failed) go to standard error. */
    private static RsLogInterface log(PrintStream err) {
        return new RsLogAdapter() {
            @Override
            public void logIt(String level, String message) {
                if (level.equals("X")) {
                    err.println("rp1.Replay: " + message);
                }
            }
        };
    }

    /** The command line. */
    private static final class Options {
        Path recording;
        Path events;
        Path snapshot;
        Path html;
        double until = Double.POSITIVE_INFINITY;

        /** The options, or null if help was asked for. */
        static Options parse(String[] args) {
            Options o = new Options();
            for (int i = 0; i < args.length; i++) {
                switch (args[i]) {
                    case "-h", "--help" -> {
                        return null;
                    }
                    case "--events" -> o.events = Paths.get(value(args, ++i, "--events"));
                    case "--snapshot" -> o.snapshot = Paths.get(value(args, ++i, "--snapshot"));
                    case "--html" -> o.html = Paths.get(value(args, ++i, "--html"));
                    case "--until" -> o.until = time(value(args, ++i, "--until"));
                    default -> {
                        if (args[i].startsWith("-") || o.recording != null) {
                            throw new IllegalArgumentException(args[i].startsWith("-") ? "unknown option " + args[i]
                                    + Suggestion.didYouMean(args[i], Suggestion.optionsIn(OPTIONS))
                                    : "unexpected argument " + args[i]);
                        }
                        o.recording = Paths.get(args[i]);
                    }
                }
            }
            if (o.recording == null) {
                throw new IllegalArgumentException("no recording given");
            }
            return o;
        }

        private static String value(String[] args, int i, String option) {
            if (i >= args.length) {
                throw new IllegalArgumentException(option + " needs a value");
            }
            return args[i];
        }

        private static double time(String v) {
            double t;
            try {
                t = Double.parseDouble(v);
            } catch (NumberFormatException e) {
                t = Double.NaN;
            }
            if (!(t >= 0.0) || Double.isInfinite(t)) {
                throw new IllegalArgumentException("--until needs a simulated time in seconds (0 or more), got " + v);
            }
            return t;
        }
    }
}
