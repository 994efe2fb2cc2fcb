package rp1.simulator.world;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

import rp1.rossum.RsBody;
import rp1.rossum.RsBodyPainter;
import rp1.rossum.RsBodyPart;
import rp1.rossum.RsBodySensor;
import rp1.rossum.RsMotion;
import rp1.rossum.RsPlan;
import rp1.rossum.RsTransform;
import rp1.rossum.RsWall;
import rp1.rossum.RsWheel;
import rp1.rossum.RsWheelSystem;
import rp1.rossum.event.RsContactSensorEvent;
import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.event.RsMotionStartedEvent;
import rp1.rossum.event.RsSensorEvent;
import rp1.rossum.request.RsMotionRequest;
import rp1.rossum.request.RsPainterChangeRequest;
import rp1.simulator.noise.RobotNoise;

/**
 * One client's robot in the world: its body, whether it is placed, its motion, the motion request
 * waiting to start, and its paint trails. The motion lifecycle of behavior.md section 5.4 lives here,
 * split into the phases the {@link MotionStepper} runs for the robots due at one time. What the
 * world's other parts need to remember about a robot (when it is next evaluated, where it is filed,
 * its contact searches) they keep themselves, by its number.
 *
 * <p>With noise (docs/behavior.md section 8.9) the robot's truth and what its client is told part
 * here, through its {@link RobotNoise}: the motion made against the one commanded, and each event
 * that reports a reading or a pose. The pose, the sensors' state and position reports stay the truth.
 *
 * <p>Everything here runs on the thread running the simulation's tasks (see
 * {@link rp1.simulator.scheduler.Scheduler}); a placement request marks the robot unplaced when it is
 * applied, so requests applied after it see the robot off the floor at once, as in RP1 0.60.
 */
public final class Robot {
    private final int number;
    private final EventSink events;
    /** Where what the client is told parts from the truth ({@link RobotNoise#NONE}: nowhere). */
    private final RobotNoise noise;
    private final RsBody body;
    private final RobotShapes shapes;
    /** Where the range and target sensors look. */
    private final Sight sight;
    private final String label;
    private final List<PaintTrail> trails;
    private boolean placed;
    private RsMotionRequest pending;
    /** The motion the pending request really makes (with wheel slip), once asked for; else null. */
    private RsMotionRequest made;
    private boolean moving;
    private boolean placementEvaluation;

    /** @param sources the world's outlines, shared by the robots of one design */
    Robot(int number, RsBody body, EventSink events, RobotNoise noise, OutlineSources sources) {
        this.number = number;
        this.noise = noise;
        this.body = body;
        this.events = events;
        this.shapes = new RobotShapes(body, sources);
        this.sight = new Sight(body);
        String name = body.getName();
        this.label = name == null || name.isEmpty() ? "robot " + number : name;
        List<PaintTrail> t = new ArrayList<>();
        for (RsBodyPainter p : body.getBodyPainterArray()) {
            t.add(new PaintTrail(p));
        }
        trails = Collections.unmodifiableList(t);
    }

    /**
     * The box, with the robot at {@code pose}, of all its range and target sensors could look at (see
     * {@link Sight#box}); one array, valid until the next call.
     */
    double[] sightBox(RsTransform pose) {
        return sight.box(pose);
    }

    /** Whether the robot has range or target sensors, which other robots can affect. */
    boolean hasWallSensors() {
        return sight.reach() > 0.0;
    }

    /**
     * Whether a reading of this robot's range or target sensors, the robot at {@code pose}, could
     * depend on {@code other} at {@code otherPose} (see it, or be blocked by it).
     */
    boolean mightSee(RsTransform pose, Robot other, RsTransform otherPose) {
        return sight.mightSee(pose, otherPose.m13, otherPose.m23, other.shapes.reach() + 1.0e-9);
    }

    /**
     * With this robot at {@code pose}, whether a reading of its range or target sensors could depend
     * on anything within a radius of a point (valid until the robot's sight is next asked about).
     */
    RobotIndex.Reach sightFrom(RsTransform pose) {
        return sight.aimedAt(pose);
    }

    /** The pose at {@code time} under the current motion (identity before the first placement). */
    RsTransform poseAt(double time) {
        return poseAt(time, new RsTransform());
    }

    /**
     * {@link #poseAt(double)} written into {@code into}, which is returned: for the searches that ask
     * for every neighbour's pose at every step and keep none of them.
     */
    RsTransform poseAt(double time, RsTransform into) {
        RsMotion m = body.getMotion();
        if (m == null) {
            into.copy(new RsTransform());
        } else {
            m.getPoseAtTime(time, into);
        }
        return into;
    }

    /** The order in which the robot joined the world, from 1 (dense: parts keep per-robot arrays by it). */
    public int getNumber() {
        return number;
    }

    /** The body's name, or "robot N" if it has none; other robots' sensors report this name. */
    public String getLabel() {
        return label;
    }

    public RsBody getBody() {
        return body;
    }

    public boolean isPlaced() {
        return placed;
    }

    /** Off the floor (the world keeps count: {@link World#unplace}). */
    void markUnplaced() {
        placed = false;
    }

    /** On the floor again (the world keeps count). */
    void markPlaced() {
        placed = true;
    }

    public boolean isMoving() {
        return moving;
    }

    /** The paint trails, one per painter part. */
    public List<PaintTrail> getTrails() {
        return trails;
    }

    EventSink events() {
        return events;
    }

    RobotShapes shapes() {
        return shapes;
    }

    RsMotion motion() {
        return body.getMotion();
    }

    /** Upper bound of the speed of any point of the robot's shapes under its current motion, m/s. */
    double speedBound() {
        return speedBound(shapes.reach());
    }

    /**
     * Upper bound of the speed, under the robot's current motion, of any point of it within
     * {@code radius} of the body origin, m/s: 0 at rest.
     */
    double speedBound(double radius) {
        RsMotion m = body.getMotion();
        if (!moving || m == null) {
            return 0.0;
        }
        return Math.abs(m.getVelocity()) + Math.abs(m.getTurnRate()) * radius;
    }

    /** The pose at the motion's current time (identity before the first placement). */
    public RsTransform pose() {
        RsMotion m = body.getMotion();
        return m == null ? new RsTransform() : m.transform;
    }

    /**
     * The pose the robot believes it has at its motion's current time, when wheel slip makes that
     * differ from {@link #pose()} (docs/behavior.md section 8.9); else null.
     */
    public RsTransform believedPose() {
        RsMotion m = body.getMotion();
        return m == null ? null : noise.believedPose(m.time);
    }

    /** Whether the motion stepper has work for this robot: moving, a request to start, or just placed. */
    boolean needsProcessing() {
        return placed && (moving || pending != null || placementEvaluation);
    }

    /** A motion request takes effect at the robot's next evaluation, replacing any motion under way. */
    void setPendingRequest(RsMotionRequest request) {
        pending = request;
        made = null;
    }

    boolean hasPendingRequest() {
        return pending != null;
    }

    /**
     * The motion the request waiting to start will really make: the request itself, or with wheel
     * slip (docs/behavior.md section 8.9) the request slipped, drawn once, so that the walls it could
     * meet are gathered for the motion made, not the one commanded; cut to {@link MotionBounds}. Only
     * when a request waits.
     */
    RsMotionRequest motionToMake() {
        if (made == null) {
            made = MotionBounds.bounded(noise.slip(pending));
        }
        return made;
    }

    /** Puts the robot at a pose with a fresh motion history; its sensors are evaluated next. */
    void place(double time, double x, double y, double orientation) {
        body.place(time, x, y, orientation);
        moving = false;
        pending = null;
        made = null;
        placementEvaluation = true;
        RsTransform at = pose();
        noise.placed(time, at.m13, at.m23, at.getTheta());
    }

    /** Step 1 of an evaluation: the motion, wheels, encoders and paint trails brought to {@code time}. */
    void advance(double time) {
        RsMotion m = body.getMotion();
        if (m == null) {
            return;
        }
        m.setTime(time);
        body.applyMotion();
        for (PaintTrail t : trails) {
            t.record(m.transform, m.getContinuitySeriesID());
        }
    }

    /**
     * Step 2: the pending request becomes the motion, cut short before any wall it would hit; motion
     * started (if it lasts), then contact-sensor releases.
     */
    void startPendingMotion(double time, RsWall[] walls) {
        RsMotionRequest request = pending;
        RsMotionRequest motion = motionToMake();
        pending = null;
        made = null;
        placementEvaluation = false;
        noise.begin(time, request);
        body.computeMotion(time, motion, walls);
        RsMotion m = body.getMotion();
        moving = true;
        if (m.timeTotal > 0.0) {
            RsTransform start = m.transform0;
            events.sendIfSubscribed(noise.started(new RsMotionStartedEvent(time, request.linearVelocity,
                    request.rotationalVelocity, m.timeTotal, start.m13, start.m23, start.getTheta())));
        }
        for (RsContactSensorEvent e : body.releaseContactSensors(time)) {
            events.sendIfSubscribed(e);
        }
    }

    /** Step 3: target, range and paint sensors at {@code time}; one event per changed, subscribed sensor. */
    void sense(double time, RsPlan plan, RsWall[] obstacles) {
        body.processSensors(time, plan, obstacles, pose());
        List<RsBodySensor> sensors = body.getBodySensors();
        for (int i = 0; i < sensors.size(); i++) {
            RsBodySensor s = sensors.get(i);
            if (s.didStateChange()) {
                events.sendIfSubscribed(noise.reading(s, time, true));
            }
        }
    }

    /**
     * Steps 4 and 5: when the motion goes on, the time of the next evaluation; when it has ended,
     * contact-sensor hits and motion halted (not after a placement), and NaN.
     */
    double finish(double time, double interval) {
        boolean wasPlacement = placementEvaluation;
        placementEvaluation = false;
        RsMotion m = body.getMotion();
        if (moving && m.time < m.time1) {
            return Math.min(m.time + interval, m.time1);
        }
        if (moving) {
            moving = false;
            for (RsContactSensorEvent e : body.pressContactSensors(time)) {
                events.sendIfSubscribed(e);
            }
            if (!wasPlacement) {
                RsTransform end = m.transform;
                int cause = m.collision ? RsMotionHaltedEvent.HALTED_ON_COLLISION : RsMotionHaltedEvent.HALTED_ON_COMPLETION;
                events.sendIfSubscribed(noise.halted(
                        new RsMotionHaltedEvent(time, cause, end.m13, end.m23, end.getTheta(), m.timeTotal)));
            }
        }
        return Double.NaN;
    }

    /** A halt request: any waiting request is dropped and a motion under way stops at {@code time}. */
    void halt(double time) {
        pending = null;
        made = null;
        if (!moving) {
            return;
        }
        RsMotion m = body.getMotion();
        m.stopMotionAtTime(time);
        m.setTime(time);
        moving = false;
        RsTransform at = m.transform;
        events.sendIfSubscribed(noise.halted(new RsMotionHaltedEvent(time, RsMotionHaltedEvent.HALTED_ON_REQUEST, at.m13,
                at.m23, at.getTheta(), m.timeTotal)));
    }

    /** Sends the position report at {@code time} (the last pose if unplaced; zeros before any placement). */
    public void reportPosition(double time) {
        events.send(body.getPositionEvent(time));
    }

    /** Whether the body has a sensor with this part id. */
    public boolean hasSensor(int id) {
        return body.getPartByID(id) instanceof RsBodySensor;
    }

    /**
     * Sends the sensor's last computed state, stamped {@code time}, whatever the subscriptions; nothing
     * if the robot is off the floor (docs/behavior.md section 8.6).
     */
    public void reportSensor(int id, double time) {
        RsBodyPart part = body.getPartByID(id);
        if (placed && part instanceof RsBodySensor) {
            RsSensorEvent e = noise.reading((RsBodySensor) part, time, false);
            if (e != null) {
                events.send(e);
            }
        }
    }

    /**
     * Sends one encoder status event per id that names a wheel of the wheel system, in order; clears
     * the accumulators after reporting if asked (docs/behavior.md section 5.8).
     *
     * @return how many ids named no wheel (skipped)
     */
    public int reportEncoders(int requestIndex, int[] ids, boolean clear, double time) {
        RsWheelSystem wheels = body.wheelSystem;
        int missing = 0;
        for (int id : ids) {
            RsWheel wheel = wheels == null ? null : wheels.getWheelForID(id);
            if (wheel == null) {
                missing++;
            } else {
                events.send(noise.encoder(wheel.getEncoderStatusEvent(time, requestIndex, clear)));
            }
        }
        return missing;
    }

    /** Applies a painter-change request to the painter with that id, if the body has one. */
    void changePainter(RsPainterChangeRequest r) {
        for (PaintTrail t : trails) {
            if (t.getPainterID() == r.painterID) {
                t.apply(r);
            }
        }
    }

    /** Clears every trail ("Remove Paint Trails"). */
    void eraseTrails() {
        for (PaintTrail t : trails) {
            t.erase();
        }
    }

    /** The robot's shapes at {@code pose}, as walls other robots sense and are placed against. */
    RsWall[] obstaclesAt(RsTransform pose) {
        return shapes.asWalls(pose, label);
    }

    @Override
    public String toString() {
        return "Robot[" + number + " " + label + (placed ? ", placed" : "") + (moving ? ", moving" : "") + "]";
    }
}
