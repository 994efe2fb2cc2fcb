package rp1.view;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;

import rp1.io.IoFailures;
import rp1.rossum.RsLogInterface;
import rp1.simulator.Simulation;
import rp1.simulator.outcome.RunStatistics;
import rp1.simulator.outcome.Trail;
import rp1.simulator.snapshot.WorldSnapshot;

/**
 * Writes PNG pictures of the world (plan, trails, robots, the path each robot took; under them the
 * simulated time and a scale bar) without any display: with an interval,
 * one at every multiple of the interval of simulated time while the world changes, named
 * {@code NAME-TTTT.TTT.EXT} after the file name given (e.g. {@code run-0012.500.png} for
 * {@code run.png} at 12.5 s); and one at {@link #close()}, under the file name itself.
 *
 * <p>The pictures are snapshots taken by an observer of the simulation
 * ({@link Simulation#observeChanges}): on the thread running tasks, after every model task due at the
 * same time (so a picture shows everything that happened up to its time), and only at times by which
 * the world has changed, so a world at rest is not kept busy. Drawing and encoding happen on a writer
 * thread; should it fall behind by more than a few pictures, the thread running tasks draws the next
 * one itself, which can slow a paced simulation but never change it.
 *
 * <p>A picture that cannot be written (a full disk) is an important line in the log and leaves no
 * file behind ({@link Pictures#writePng}); {@link #close()} then throws, so the server's exit status
 * says that its output is not whole.
 */
public final class SnapshotWriter implements AutoCloseable {
    private static final int QUEUED_PICTURES = 4;
    private static final long CLOSE_WAIT_SECONDS = 60;

    private final Simulation simulation;
    private final Renderer renderer;
    private final Path file;
    private final double interval;
    private final RsLogInterface log;
    private final ThreadPoolExecutor writer;
    private final AutoCloseable observation;
    /** Where the robots went, for the paths drawn in the pictures. */
    private final RunStatistics paths;
    private boolean closed;
    private volatile String failure;

    /**
     * @param simulation the simulation to picture
     * @param file       where the picture at exit goes; interval pictures are named after it
     * @param interval   simulated seconds between pictures; 0 for the picture at exit only
     * @param log        where write failures are reported
     */
    public SnapshotWriter(Simulation simulation, Path file, double interval, RsLogInterface log) {
        if (!(interval >= 0.0) || Double.isInfinite(interval)) {
            throw new IllegalArgumentException("snapshotInterval must be finite and not negative, got " + interval);
        }
        this.simulation = simulation;
        this.renderer = new Renderer(simulation.getWorld().getPlan());
        this.file = file;
        this.interval = interval;
        this.log = log;
        // The writer is made when the first picture is taken, on the simulation's thread, whose group
        // holds the robots' threads, which are ended with the run: it belongs with this one's.
        ThreadGroup group = Thread.currentThread().getThreadGroup();
        this.writer = new ThreadPoolExecutor(1, 1, 0L, TimeUnit.MILLISECONDS, new ArrayBlockingQueue<>(QUEUED_PICTURES),
                r -> {
                    Thread t = new Thread(group, r, "rp1-snapshot-writer");
                    t.setDaemon(true);
                    return t;
                }, new ThreadPoolExecutor.CallerRunsPolicy());
        this.paths = RunStatistics.watch(simulation);
        this.observation = interval > 0.0 ? simulation.observeChanges(interval, this::picture) : () -> { };
    }

    /** The file name of the picture at {@code simTime}: the time inserted before the extension. */
    public static Path fileAt(Path file, double simTime) {
        String name = file.getFileName().toString();
        int dot = name.lastIndexOf('.');
        String stem = dot > 0 ? name.substring(0, dot) : name;
        String extension = dot > 0 ? name.substring(dot) : "";
        return file.resolveSibling(String.format(Locale.ROOT, "%s-%08.3f%s", stem, simTime, extension));
    }

    /** An interval picture, on the thread running tasks. */
    private synchronized void picture(double simTime) {
        if (!closed) {
            submit(WorldSnapshot.of(simulation, simTime), paths.trails(), fileAt(file, simTime));
        }
    }

    private void submit(WorldSnapshot snapshot, List<Trail> trails, Path target) {
        writer.execute(() -> write(snapshot, trails, target));
    }

    private void write(WorldSnapshot snapshot, List<Trail> trails, Path target) {
        try {
            Pictures.writePng(Pictures.renderCaptioned(renderer, snapshot, trails), target);
        } catch (IOException | RuntimeException e) {
            String why = "cannot write the picture " + target + ": "
                    + (e instanceof IOException io ? IoFailures.why(io) : e.getMessage());
            if (failure == null) {
                failure = why;
            }
            log.logIt("X", why);
        }
    }

    /**
     * Writes the picture at exit and waits (up to a minute) until every picture is on disk. Call
     * once the scheduler has stopped; the world is then read from the calling thread.
     *
     * @throws IOException naming the first picture that could not be written (the others were)
     */
    @Override
    public void close() throws IOException {
        synchronized (this) {
            if (closed) {
                return;
            }
            closed = true;
        }
        try {
            observation.close();
        } catch (Exception e) {
            log.log("Could not stop the interval pictures: " + e);
        }
        submit(WorldSnapshot.atRecordedTime(simulation), paths.trails(), file);
        writer.shutdown();
        try {
            if (!writer.awaitTermination(CLOSE_WAIT_SECONDS, TimeUnit.SECONDS)) {
                failure = "pictures still being written after " + CLOSE_WAIT_SECONDS + " s; given up";
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        if (failure != null) {
            throw new IOException(failure);
        }
    }
}
