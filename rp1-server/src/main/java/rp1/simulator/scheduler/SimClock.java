package rp1.simulator.scheduler;

/**
 * The simulation clock (docs/behavior.md section 4.2). Three kinds:
 * <ul>
 * <li>Paced: simulation time follows absolute deadlines, {@code speed} simulated seconds per wall second
 * since the clock began. A task is never run before its deadline; when the simulation falls behind (a
 * late wake-up, a client slow to acknowledge an event) the tasks that have fallen due run back to back
 * until it has caught up, so lateness is made up instead of accumulating. The catching up is bounded:
 * the clock is never more than {@link #MAX_LAG_SECONDS} of wall time behind the work that fell due, so
 * a long pause (a debugger, a client that thinks for a minute) is not followed by a burst of that
 * length; time with nothing due passes as the wall clock says.</li>
 * <li>Lockstep ({@link #lockstep()}, {@code simulationSpeed=max}): the wall clock is never read; time
 * jumps to each task as it runs.</li>
 * <li>Replay ({@link #replay()}): lockstep that cannot be held. A replay runs the recorded task
 * sequence and applies each recorded input before the task it came before; whatever held time back
 * in the recorded run is already in that sequence, so a hold of the replay's own would only stall it.</li>
 * </ul>
 *
 * <p>Four ways to hold time back: before {@link #begin()} nothing runs; while {@link #stop(double) stopped}
 * (the interlock waits for a client) nothing runs and time is frozen; while {@link #hold() held}
 * (waiting for clients to place their robots) time cannot advance, but work due at the current time
 * still runs; while {@link #pause(double) paused} (the user, in the window) time cannot pass a limit,
 * the time it was paused at plus whatever {@link #step(double, double) steps} allowed since. Each
 * has its own flag, so the clock runs only when none of them holds it.
 *
 * <p>The user may also change the speed while the run goes on ({@link #setSpeed(double, double)}),
 * paced to lockstep and back. All of this changes only how fast simulated time passes against the
 * wall clock, never which tasks run at which simulated time. Not thread-safe on its own: the
 * {@link Scheduler} guards it.
 */
public final class SimClock {
    /** How far, in wall seconds, a paced clock may fall behind its deadlines before it gives up catching up. */
    public static final double MAX_LAG_SECONDS = 1.0;

    private final TimeSource wall;
    private double speed;
    private boolean lockstep;
    private final boolean holdable;
    private boolean begun;
    private boolean stopped;
    private boolean held;
    private boolean paused;
    /** While paused, the time the clock may not pass; infinity otherwise. */
    private double limit = Double.POSITIVE_INFINITY;
    private double simTime;
    private long wallAnchor;
    private double simAnchor;

    private SimClock(TimeSource wall, double speed, boolean lockstep, boolean holdable) {
        this.wall = wall;
        this.speed = speed;
        this.lockstep = lockstep;
        this.holdable = holdable;
    }

    /**
     * A clock paced by {@code wall} at {@code speed} simulated seconds per wall second.
     *
     * @throws IllegalArgumentException if speed is not positive and finite
     */
    public static SimClock paced(TimeSource wall, double speed) {
        if (!(speed > 0.0) || Double.isInfinite(speed)) {
            throw new IllegalArgumentException("simulation speed must be positive and finite, got " + speed);
        }
        return new SimClock(wall, speed, false, true);
    }

    /** A clock that never reads the wall clock: time is the time of the task being run. */
    public static SimClock lockstep() {
        return lockstep(TimeSource.SYSTEM);
    }

    /** A lockstep clock that reads {@code wall} only if it is {@link #setSpeed(double, double) slowed down}. */
    public static SimClock lockstep(TimeSource wall) {
        return new SimClock(wall, Double.POSITIVE_INFINITY, true, true);
    }

    /** A lockstep clock on which {@link #hold()} has no effect, for replaying a recorded run. */
    public static SimClock replay() {
        return new SimClock(null, Double.POSITIVE_INFINITY, true, false);
    }

    public boolean isLockstep() {
        return lockstep;
    }

    /** Whether tasks may run: the clock has begun and the interlock does not hold it. */
    boolean canRun() {
        return begun && !stopped;
    }

    boolean isBegun() {
        return begun;
    }

    boolean isStopped() {
        return stopped;
    }

    boolean isHeld() {
        return held;
    }

    /** Begins the run: deadlines count from now. Does nothing if it has begun. */
    void begin() {
        if (!begun) {
            begun = true;
            anchor();
        }
    }

    private void anchor() {
        if (!lockstep) {
            wallAnchor = wall.nanoTime();
            simAnchor = simTime;
        }
    }

    /** Freezes time after bringing it up to date (limited by {@code horizon}); no task runs until {@link #resume()}. */
    void stop(double horizon) {
        if (!stopped) {
            update(horizon);
            stopped = true;
        }
    }

    /**
     * Ends a {@link #stop(double)}; the deadlines are not moved, so time lost while stopped is caught
     * up, as far as {@link #MAX_LAG_SECONDS} allows: time stood still at the time it was stopped at.
     */
    void resume() {
        if (stopped) {
            stopped = false;
            if (!lockstep && begun && !held) {
                keepWithinLag(simTime);
            }
        }
    }

    /** Time may not advance until {@link #release()}; work due now still runs. Not on a replay clock. */
    void hold() {
        held = holdable;
    }

    /** Freezes time after bringing it up to date (limited by {@code horizon}) until {@link #unpause()}. */
    void pause(double horizon) {
        if (!paused) {
            update(horizon);
            paused = true;
            limit = simTime;
        }
    }

    /** Ends a {@link #pause(double)}: time runs on from here, deadlines counting from now. */
    void unpause() {
        if (paused) {
            paused = false;
            limit = Double.POSITIVE_INFINITY;
            anchor();
        }
    }

    /**
     * Lets a paused clock (pausing it first if it runs) advance {@code seconds} more, at its speed
     * from now, and then stand still again.
     */
    void step(double horizon, double seconds) {
        pause(horizon);
        update(horizon);
        limit += seconds;
        anchor();
    }

    boolean isPaused() {
        return paused;
    }

    /** The time a paused clock may not pass (infinity when not paused). */
    double limit() {
        return limit;
    }

    /**
     * Changes the speed: {@code newSpeed} simulated seconds per wall second, or lockstep for infinity.
     * Time is brought up to date (limited by {@code horizon}) first and the deadlines count from there,
     * so time never goes back. A replay clock stays lockstep.
     *
     * @throws IllegalArgumentException if the speed is not positive
     */
    void setSpeed(double horizon, double newSpeed) {
        if (!(newSpeed > 0.0)) {
            throw new IllegalArgumentException("simulation speed must be positive, got " + newSpeed);
        }
        if (!holdable) {
            return;
        }
        update(horizon);
        speed = newSpeed;
        lockstep = Double.isInfinite(newSpeed);
        anchor();
    }

    /** The speed: simulated seconds per wall second, infinity in lockstep. */
    public double getSpeed() {
        return speed;
    }

    /** Ends a {@link #hold()}: time runs on from here, deadlines counting from now. */
    void release() {
        if (held) {
            held = false;
            anchor();
        }
    }

    /**
     * Advances simulation time to what the deadlines say, but never past {@code horizon} (the time of
     * the first queued timed task); returns the updated time. Time never goes back: a horizon in the
     * past (a negative timeout waiting to run) or not a number leaves it where it is. Lockstep, stopped,
     * held and not yet begun clocks do not move; a paused one not past its limit.
     *
     * <p>The clock is behind only where work has fallen due: up to the horizon, time passed with
     * nothing to do (a client thinking while no task is queued, the scheduler asleep until the next
     * one), and that time is not lost. Counting it as lag took up to four fifths of such a run's time
     * away: a paced run with nothing queued before its end ran at a fifth of its speed.
     */
    double update(double horizon) {
        if (!lockstep && begun && !stopped && !held) {
            double estimate = keepWithinLag(Math.max(simTime, horizon));
            double reached = Math.min(Math.min(estimate, horizon), limit);
            if (reached > simTime) {
                simTime = reached;
            }
        }
        return simTime;
    }

    /**
     * What the deadlines say simulation time is now, after moving them so that it is at most
     * {@link #MAX_LAG_SECONDS} of wall time past {@code base}, the time the clock could have kept up
     * to (a base that is not a number moves nothing).
     */
    private double keepWithinLag(double base) {
        double estimate = estimate();
        double maxLag = MAX_LAG_SECONDS * speed;
        if (estimate - base > maxLag) {
            simAnchor -= estimate - base - maxLag;
            estimate = base + maxLag;
        }
        return estimate;
    }

    /** What the deadlines say simulation time is now (paced clocks only). */
    private double estimate() {
        return simAnchor + (wall.nanoTime() - wallAnchor) * 1.0e-9 * speed;
    }

    /** The current simulation time, as last updated. */
    public double getSimTime() {
        return simTime;
    }

    /** Sets the time the task about to run is stamped with (lockstep). */
    void setSimTime(double t) {
        simTime = t;
    }

    /** Whether a lockstep clock may jump to {@code time}: not held, and not past a pause's limit. */
    boolean mayJumpTo(double time) {
        return lockstep && !held && time <= limit;
    }

    /** Wall nanoseconds until the deadline of simulation time {@code target} (paced clocks only). */
    long nanosUntil(double target) {
        return (long) Math.ceil((target - estimate()) / speed * 1.0e9);
    }
}
