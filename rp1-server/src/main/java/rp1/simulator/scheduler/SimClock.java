package rp1.simulator.scheduler;

/**
 * The simulation clock (behavior.md section 4.2). Paced: while running, simulation time follows wall
 * time multiplied by the speed, {@code E = s0 + (wall - w0) * speed}, and the scheduler lets it advance
 * only up to the next task. Lockstep ({@link #lockstep()}, the {@code simulationSpeed=max} setting):
 * the wall clock is never read and time jumps from task to task as fast as they can be run.
 *
 * <p>"Stopped" means frozen: the interlock stops the clock while a client handles an event, and no
 * task runs until it is started again. Not thread-safe on its own: the {@link Scheduler} guards it.
 */
public final class SimClock {
    private final TimeSource wall;
    private final double speed;
    private final boolean lockstep;
    private boolean running;
    private double simTime;
    private long wallAnchor;
    private double simAnchor;

    private SimClock(TimeSource wall, double speed, boolean lockstep) {
        this.wall = wall;
        this.speed = speed;
        this.lockstep = lockstep;
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
        return new SimClock(wall, speed, false);
    }

    /** A clock that never reads the wall clock: time is the time of the task being run. */
    public static SimClock lockstep() {
        return new SimClock(null, Double.POSITIVE_INFINITY, true);
    }

    public boolean isLockstep() {
        return lockstep;
    }

    /** Simulated seconds per wall second (infinite in lockstep). */
    public double getSpeed() {
        return speed;
    }

    public boolean isRunning() {
        return running;
    }

    /** Starts (or restarts) the clock at the current simulation time. */
    void start() {
        if (!running) {
            if (!lockstep) {
                wallAnchor = wall.nanoTime();
                simAnchor = simTime;
            }
            running = true;
        }
    }

    /** Freezes the clock after bringing it up to date (limited by {@code horizon}). */
    void stop(double horizon) {
        if (running) {
            update(horizon);
            running = false;
        }
    }

    /**
     * Advances simulation time to what the wall clock says, but never past {@code horizon} (the time
     * of the first queued timed task); returns the updated time. Lockstep and stopped clocks do not move.
     */
    double update(double horizon) {
        if (running && !lockstep) {
            double estimate = estimate();
            if (estimate > simTime) {
                simTime = Math.min(estimate, horizon);
            }
        }
        return simTime;
    }

    /** What the wall clock says simulation time is now (paced clocks only). */
    double estimate() {
        return simAnchor + (wall.nanoTime() - wallAnchor) * 1.0e-9 * speed;
    }

    /** The current simulation time, as last updated. */
    public double getSimTime() {
        return simTime;
    }

    /** Sets the time the task about to run is stamped with. */
    void setSimTime(double t) {
        simTime = t;
    }

    /** Wall milliseconds until the estimate reaches {@code target} (paced clocks only). */
    long millisUntil(double target) {
        return Math.round((target - estimate()) / speed * 1000.0);
    }
}
