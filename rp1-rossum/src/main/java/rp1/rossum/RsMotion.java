package rp1.rossum;

import java.util.Map;
import java.util.WeakHashMap;

/**
 * One segment of a robot's path: from a start pose at {@link #time0}, for {@link #timeTotal}
 * seconds, until {@link #time1}. Poses are analytic (no integration): {@link #setTime} moves the
 * motion's "current" time and pose, and the pose at any time is available. A motion may be cut short
 * by a predicted collision ({@link #truncateForCollision}) or a halt ({@link #stopMotionAtTime}).
 *
 * <p>Each motion has a continuity id; motions that continue one another (each built from the previous
 * one) share a continuity series id, and a new placement starts a new series, so a paint trail knows
 * when the robot jumped. The ids count along a robot's motions (the first motion is 1, each motion
 * built from another or placed after it the next number; a series is named by its first motion), so
 * they belong to the robot and come out the same in every simulation.
 */
public abstract class RsMotion extends RsComponent {
    private static final long serialVersionUID = 1L;

    /**
     * Only for {@link #getNewContinuityID()}, which 0.60 programs may call (the library never does): the
     * last number given, per class loader of the caller. One process is one run in 0.60; here a sweep
     * runs many in one process, each robot that calls it with classes loaded for that run alone.
     */
    private static final Map<ClassLoader, int[]> LAST_CONTINUITY_IDS = new WeakHashMap<>();
    private static final StackWalker CALLERS = StackWalker.getInstance(StackWalker.Option.RETAIN_CLASS_REFERENCE);

    /** Start time (simulation seconds). */
    public double time0;
    /** End time: time0 + timeTotal. */
    public double time1;
    /** Duration in seconds. */
    public double timeTotal;
    /** The current time, in [time0, time1]. */
    public double time;
    /** Time for the robot to move about 1 mm or turn about 1 mrad (infinite when it does not move). */
    public double significantDeltaT = Double.POSITIVE_INFINITY;
    /** Pose (body to world) at time0. */
    public RsTransform transform0;
    /** Pose at the current time. */
    public RsTransform transform;
    /** Whether a collision was predicted for this motion. */
    public boolean collision;
    /** The predicted first-contact time, seconds after time0 (meaningful when {@link #collision}). */
    public double collisionTime;
    /** This motion's own continuity id ({@link #getContinuityID()}). */
    protected int continuityID;
    /** The id shared by motions that continue one another ({@link #getContinuitySeriesID()}). */
    protected int continuitySeriesID;

    /** A motion at rest at the origin at time 0, starting a new continuity series. */
    protected RsMotion() {
        transform0 = new RsTransform();
        transform = new RsTransform();
        continuityID = 1;
        continuitySeriesID = continuityID;
    }

    /**
     * A motion that starts where {@code previous} is at {@code startTime} (its pose clamped to its own
     * time span) and continues its continuity series; with a null previous it starts at the origin
     * and begins a new series.
     *
     * @param previous the motion this one follows, or null
     * @param startTime simulation time of the start, seconds
     * @param duration seconds (negative values count as 0)
     */
    public RsMotion(RsMotion previous, double startTime, double duration) {
        time0 = startTime;
        timeTotal = Math.max(0.0, duration);
        time1 = time0 + timeTotal;
        time = time0;
        transform0 = previous == null ? new RsTransform() : previous.getStateAtTime(startTime);
        transform = new RsTransform(transform0);
        continuityID = previous == null ? 1 : previous.continuityID + 1;
        continuitySeriesID = previous == null ? continuityID : previous.continuitySeriesID;
    }

    /**
     * Makes this motion, which starts a new series, the one after {@code before} in the robot's
     * history (a placement after earlier motions), so that its series differs from every earlier one.
     */
    void startSeriesAfter(RsMotion before) {
        if (before != null) {
            continuityID = before.continuityID + 1;
            continuitySeriesID = continuityID;
        }
    }

    /**
     * Moves the current time to {@code t} (clamped to [time0, time1]) and updates the current pose.
     *
     * @return whether the motion is still under way (has not reached time1)
     */
    public boolean setTime(double t) {
        time = clamp(t);
        applyTime();
        return time < time1;
    }

    /** As {@link #setTime}, but never moves the current time backwards. */
    public boolean setTimeForward(double t) {
        if (t > time) {
            return setTime(t);
        }
        return time < time1;
    }

    /** Ends the motion at {@code t} (clamped to [time0, time1]); the current time follows if it was later. */
    public void stopMotionAtTime(double t) {
        cutTo(clamp(t) - time0);
    }

    /** Shortens the motion to {@code duration} seconds. */
    final void cutTo(double duration) {
        timeTotal = duration;
        time1 = time0 + duration;
        if (time > time1) {
            time = time1;
        }
        applyTime();
    }

    /** {@code t} limited to the motion's time span. */
    final double clamp(double t) {
        return Math.max(time0, Math.min(t, time1));
    }

    /** Updates {@link #transform} (and any other state) for the current {@link #time}. */
    protected abstract void applyTime();

    /** A new transform holding the pose at {@code t} (clamped to [time0, time1]). */
    protected abstract RsTransform getStateAtTime(double t);

    /** The pose at {@code t} (clamped to the motion's time span), as a new transform. */
    public RsTransform getPoseAtTime(double t) {
        return getStateAtTime(t);
    }

    /**
     * Writes the pose at {@code t} into {@code into}: bit for bit what {@link #getPoseAtTime(double)}
     * gives, without a new transform. The server's contact search asks for two poses at each of its
     * samples, a third of what a crowd of robots allocated.
     */
    public void getPoseAtTime(double t, RsTransform into) {
        into.copy(getStateAtTime(t));
    }

    /** For a motion that computes its poses in place: the pose at {@code t} in a new transform. */
    final RsTransform poseInNewTransform(double t) {
        RsTransform pose = new RsTransform();
        getPoseAtTime(t, pose);
        return pose;
    }

    /**
     * How the body point (x, y) (body coordinates) moves at the current time: its world position, its
     * velocity, the body heading and whether the motion is under way. Wheels use it for their encoders
     * and for drawing casters along their direction of travel.
     */
    public abstract RsMotionDepiction getMotionDepictionAtBodyPoint(double x, double y);

    /**
     * Searches the whole motion for the first contact between a body outline and wall edges (both in
     * world coordinates; the body at the start pose, {@link #transform0}). A contact earlier than any
     * recorded so far is stored in {@link #collision} and {@link #collisionTime}. A motion that does
     * not move never collides.
     *
     * @return whether these edges come into contact during the motion
     */
    public boolean processCollision(RsSegment[] body, int nBody, RsSegment[] walls, int nWalls) {
        return false;
    }

    /**
     * The first-contact time (seconds after time0) of the body edges with the wall edges over the whole
     * motion, or positive infinity. Nothing is recorded.
     */
    double contactTime(RsSegment[] body, int nBody, RsSegment[] walls, int nWalls) {
        return Double.POSITIVE_INFINITY;
    }

    /**
     * Whether the body cannot touch the walls before {@code t} seconds after the motion's start: a
     * cheap bound that lets a search which has found a contact skip walls farther along the way.
     * False when this motion has no such bound.
     */
    boolean cannotMeetBefore(RsSegment[] body, int nBody, RsSegment[] walls, int nWalls, double t) {
        return false;
    }

    /**
     * What {@link #processCollision(RsSegment[], int, RsSegment[], int, double[])} and
     * {@link #cannotMeetBefore(RsSegment[], int, RsSegment[], int, double, double[])} can work out
     * once for a body searched against many walls, or null (nothing to work out, or a subclass of the
     * library's motions, which searches its own way).
     */
    double[] prepare(RsSegment[] body, int nBody) {
        return null;
    }

    /** {@link #processCollision(RsSegment[], int, RsSegment[], int)}, given what {@link #prepare} gave. */
    boolean processCollision(RsSegment[] body, int nBody, RsSegment[] walls, int nWalls, double[] prepared) {
        return processCollision(body, nBody, walls, nWalls);
    }

    /** {@link #cannotMeetBefore(RsSegment[], int, RsSegment[], int, double)}, given what {@link #prepare} gave. */
    boolean cannotMeetBefore(RsSegment[] body, int nBody, RsSegment[] walls, int nWalls, double t, double[] prepared) {
        return cannotMeetBefore(body, nBody, walls, nWalls, t);
    }

    /** {@link #contactTime(RsSegment[], int, RsSegment[], int)}, given what {@link #prepare} gave. */
    double contactTime(RsSegment[] body, int nBody, RsSegment[] walls, int nWalls, double[] prepared) {
        return contactTime(body, nBody, walls, nWalls);
    }

    /** Records a contact time found by a search; returns whether there was one. */
    final boolean recordContact(double t) {
        if (Double.isInfinite(t)) {
            return false;
        }
        if (!collision || t < collisionTime) {
            collisionTime = t;
        }
        collision = true;
        return true;
    }

    /** Rate of change of heading, rad/s (0 unless turning). */
    public double getTurnRate() {
        return 0.0;
    }

    /** Speed of the body origin as a position event reports it, m/s (0 when not moving). */
    public double getVelocity() {
        return 0.0;
    }

    /** The current time of the motion (simulation seconds). */
    public double getTime() {
        return time;
    }

    /** Position of the body origin at the current time. */
    public RsPoint getPosition() {
        return transform.getOffset();
    }

    /** Heading at the current time, radians in (-pi, pi]. */
    public double getOrientation() {
        return transform.getTheta();
    }

    /**
     * If a collision was predicted, ends the motion at the last whole millisecond at least 0.1 ms
     * before the contact: duration max(0, floor(1000 t - 0.1) / 1000).
     */
    public void truncateForCollision() {
        if (collision) {
            cutTo(collisionDeltaT(collisionTime));
        }
    }

    /**
     * A new number from a counter, as in RP1 0.60: 1, 2, 3, ... Kept so that 0.60 programs compile;
     * motions no longer take their ids from it (see the class comment). 0.60's counter was the
     * process's; this one is that of the caller's class loader, which in a program of its own is the
     * same thing, and in a sweep is the run's (a robot that calls it gets its classes loaded for each
     * run), so that a run's numbers do not depend on the runs before it.
     */
    public static int getNewContinuityID() {
        ClassLoader loader = CALLERS.getCallerClass().getClassLoader();
        synchronized (LAST_CONTINUITY_IDS) {
            return ++LAST_CONTINUITY_IDS.computeIfAbsent(loader, l -> new int[1])[0];
        }
    }

    /** This motion's own continuity id. */
    public int getContinuityID() {
        return continuityID;
    }

    /** The id shared by motions that continue one another without a jump. */
    public int getContinuitySeriesID() {
        return continuitySeriesID;
    }

    /** The duration a motion keeps when its first contact is {@code contactTime} seconds after its start. */
    protected double collisionDeltaT(double contactTime) {
        return stopTimeForContact(contactTime);
    }

    /**
     * max(0, floor(1000 t - 0.1) / 1000): the stop time for a contact t seconds into a motion
     * (behavior.md section 6.2), against a wall or, in the server, another robot.
     */
    public static double stopTimeForContact(double contactTime) {
        return Math.max(0.0, Math.floor(1000.0 * contactTime - 0.1) / 1000.0);
    }

    /** Sets {@link #significantDeltaT} for a body moving at {@code speed} m/s and turning at {@code rate} rad/s. */
    final void setSignificantDeltaT(double speed, double rate) {
        double fastest = Math.max(Math.abs(speed), Math.abs(rate));
        significantDeltaT = fastest > 0.0 ? 0.001 / fastest : Double.POSITIVE_INFINITY;
    }

    @Override
    public String toString() {
        return getClass().getSimpleName() + "[" + time0 + ".." + time1 + ", now " + time + ", " + transform + "]";
    }
}
