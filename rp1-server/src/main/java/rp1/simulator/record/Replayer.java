package rp1.simulator.record;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import rp1.planparser.RsParsingException;
import rp1.planparser.RsPlanParser;
import rp1.rossum.RsConnection;
import rp1.rossum.RsLogInterface;
import rp1.rossum.RsPlan;
import rp1.simulator.Simulation;
import rp1.simulator.SimulationSettings;
import rp1.simulator.config.ConfigException;
import rp1.simulator.config.ServerConfig;
import rp1.simulator.scheduler.Scheduler;
import rp1.simulator.session.ClientInput;
import rp1.simulator.session.ClientSession;

/**
 * Rebuilds a recorded run without its clients: the world from the recorded properties, plan and
 * seed, a session for every client that had one, and then the recorded task sequence, each input
 * applied just before the task it came before in the run, stamped with its recorded time. Nothing
 * here reads the wall clock, so a paced run replays as exactly as a lockstep one; events go nowhere
 * but to the listeners (an event log), and the world can be pictured wherever the replay stops.
 */
public final class Replayer {
    private final Recording recording;
    private final Simulation simulation;
    private final List<ClientSession> sessions = new ArrayList<>();
    private final EventStream events;

    private Replayer(Recording recording, Simulation simulation, EventStream events) {
        this.recording = recording;
        this.simulation = simulation;
        this.events = events;
    }

    /**
     * How far a replay got.
     *
     * @param partial whether the recording ran out before the replay got where it was asked to stop:
     *                it has no end line (the run did not stop cleanly), and its last input was applied
     */
    public record Outcome(long tasks, double time, long events, boolean complete, boolean partial, String difference) {
        /** Whether the replay reached the recorded end and sent exactly the recorded events. */
        public boolean matches() {
            return complete && difference == null;
        }
    }

    /**
     * Prepares the replay of {@code recording}, writing the events to {@code eventLog} (or nowhere if
     * null).
     *
     * @throws RecordingException if the recorded properties or floor plan are not valid here
     * @throws IOException        if the event log cannot be created
     */
    public static Replayer prepare(Recording recording, Path eventLog, RsLogInterface log)
            throws RecordingException, IOException {
        ServerConfig config;
        try {
            config = ServerConfig.fromRecorded(recording.propertiesTable(), recording.file() + " (its properties)");
        } catch (ConfigException e) {
            throw new RecordingException(e.getMessage(), e);
        }
        RsPlan plan;
        try {
            plan = RsPlanParser.parse(recording.planText(), recording.planName());
        } catch (RsParsingException e) {
            throw new RecordingException(recording.file() + ": its floor plan does not parse here: " + e.getMessage(), e);
        }
        SimulationSettings settings = SimulationSettings.of(config, recording.seed()).forReplay();
        Simulation simulation = new Simulation(plan, settings, log);
        EventStream events = eventLog == null ? EventStream.counting() : EventStream.toFile(eventLog, log);
        simulation.addEventListener(events);
        Replayer replayer = new Replayer(recording, simulation, events);
        replayer.attachClients();
        return replayer;
    }

    /**
     * One session per client number, in order, so each gets the number it had. Their connections
     * have no stream: what is sent to them goes nowhere.
     */
    private void attachClients() {
        for (int n = 1; n <= recording.maxClient(); n++) {
            String description = recording.clients().getOrDefault(n, "client " + n);
            sessions.add(simulation.attach(new RsConnection(), description, Simulation.Link.DIRECT));
        }
    }

    /** Why the replay's event log could not be written whole, or null. */
    public String eventLogFailure() {
        return events.failure();
    }

    /** The simulation being replayed (its world is what a picture shows). */
    public Simulation simulation() {
        return simulation;
    }

    /**
     * Replays the run up to its end, or up to simulated time {@code until} (every task and input due
     * by then), then finishes the event log ({@link #eventLogFailure()} says if it could not be written).
     *
     * @throws RecordingException if the run cannot be followed: tasks run out before an input's place
     */
    public Outcome run(double until) throws RecordingException {
        try {
            return replay(until);
        } finally {
            events.close();
        }
    }

    private Outcome replay(double until) throws RecordingException {
        Scheduler scheduler = simulation.getScheduler();
        simulation.startClock();
        for (Recording.Step step : recording.steps()) {
            if (!runTo(step.task(), until, step.line()) || step.time() > until) {
                return stopped(until);
            }
            apply(step);
        }
        Recording.End end = recording.end();
        if (end == null) {
            return new Outcome(scheduler.modelTasksRun(), scheduler.recordedTime(), events.count(), false, true, null);
        }
        if (!runTo(end.tasks(), until, end.line())) {
            return stopped(until);
        }
        return new Outcome(end.tasks(), end.time(), events.count(), true, false, difference(end));
    }

    private Outcome stopped(double until) {
        return new Outcome(simulation.getScheduler().modelTasksRun(), until, events.count(), false, false, null);
    }

    /** Runs model tasks until {@code tasks} have run; false if the next one is due after {@code until}. */
    private boolean runTo(long tasks, double until, int line) throws RecordingException {
        Scheduler scheduler = simulation.getScheduler();
        while (scheduler.modelTasksRun() < tasks) {
            if (scheduler.nextTaskTime() > until) {
                return false;
            }
            if (!scheduler.runNext()) {
                throw new RecordingException(recording.file() + ":" + line + ": the replay has no task left after "
                        + scheduler.modelTasksRun() + " of the " + tasks + " the run had run by then: the recording"
                        + " does not match this simulator's world model");
            }
        }
        return true;
    }

    private void apply(Recording.Step step) {
        simulation.getScheduler().advanceTo(step.time());
        if (step.action() != null) {
            step.action().applyTo(simulation, step.time());
        } else {
            new ClientInput(sessions.get(step.source() - 1), step.request()).apply(step.time());
        }
    }

    /** What differs between the events of the replay and those of the run, or null. */
    private String difference(Recording.End end) {
        if (events.count() != end.events()) {
            return "the replay sent " + events.count() + " events, the run " + end.events();
        }
        if (events.checksum() != end.checksum()) {
            return "the replay sent other events than the run (same number, CRC-32 " + Long.toHexString(events.checksum())
                    + " instead of " + Long.toHexString(end.checksum()) + ")";
        }
        return null;
    }
}
