package rp1.rossum;

import java.awt.Graphics;
import java.util.ArrayList;
import java.util.List;
import rp1.rossum.event.RsContactSensorEvent;
import rp1.rossum.event.RsPositionEvent;
import rp1.rossum.request.RsMotionRequest;

/**
 * A robot body: its parts in the order they were added (which is also the drawing order), its wheel
 * system, and, in the simulator, its current motion and whether it is placed. The body plan is in
 * body coordinates (x forward, y left, origin at the robot's reference point, e.g. the axle centre).
 *
 * <p>On the simulator side the body carries the model's per-robot work: interpreting motion requests
 * (behavior.md section 5.2), the collision search that truncates a motion (section 6), the placement
 * clear test (section 7), sensor evaluation (section 8) and position reports (section 5.7).
 */
public class RsBody extends RsComponent {
    private static final long serialVersionUID = 1L;

    /** The body's name, sent with the body specification. */
    public String name;
    /** The wheel system added with {@link #addPart}, or null. */
    public RsWheelSystem wheelSystem;
    /** The current motion (simulator side), or null before the first placement. */
    public RsMotion motion;
    /** Bounding box of all parts, body coordinates. */
    public RsRectangle refBounds = new RsRectangle();
    /** The edges of {@link #refBounds}, body coordinates. */
    public RsSegment[] refEnclosure = new RsSegment[0];
    /** Whether the robot is placed in the simulation. */
    public boolean placement;
    /** Whether the current motion was cut short by a predicted collision. */
    public boolean collision;

    /** What {@link #releaseContactSensors} and {@link #pressContactSensors} return when no sensor changes: empty, so shared. */
    private static final RsContactSensorEvent[] NO_CONTACT_EVENTS = new RsContactSensorEvent[0];

    private final ArrayList<RsBodyPart> parts = new ArrayList<>();
    /**
     * The sensors in part order, a list that cannot be changed, kept because the simulator reads them
     * at every motion step of every robot; rebuilt when a part is added.
     */
    private transient List<RsBodySensor> sensors;
    /** The interactive shapes in part order, kept for the same reason (every motion is searched with them). */
    private transient RsBodyShape[] interactive;
    /** The contact sensors in part order, kept for the same reason (looked at at every motion's start and end). */
    private transient RsBodyContactSensor[] contactSensors;
    /** Each contact sensor's outline where the last motion started, placed again when one starts elsewhere. */
    private transient RsSegment[][] contactOutlines;
    /**
     * The interactive shapes' outlines where the last motion started, one after another in part order,
     * placed again when one starts elsewhere: the collision search takes them as one body, so that a
     * wall is searched once for all the parts rather than once per part.
     */
    private transient RsSegment[] interactiveOutline;
    /**
     * Where {@link #interactiveOutline} and {@link #contactOutlines} were last placed, both by the same
     * search (null: not yet). A robot halted as soon as it starts a motion starts the next one from the
     * same pose: in a crowd of a thousand wanderers, two thirds of the motions started where the one
     * before had, and their outlines are kept rather than placed again. The shapes' outlines never
     * change once built.
     */
    private transient RsTransform outlinesPlacedAt;
    private int bodyID;

    /** An empty body; null is kept as the name and transmitted as "". */
    public RsBody(String name) {
        this.name = name;
    }

    /**
     * Adds a part (drawn after the parts added before it). Adding a wheel system makes it the body's
     * {@link #wheelSystem}.
     *
     * @throws IllegalArgumentException if part is null
     */
    public void addPart(RsBodyPart part) {
        if (part == null) {
            throw new IllegalArgumentException("part is null");
        }
        parts.add(part);
        sensors = null;
        interactive = null;
        contactSensors = null;
        outlinesPlacedAt = null;
        part.joined(this);
        if (part instanceof RsWheelSystem) {
            wheelSystem = (RsWheelSystem) part;
        }
        updateRefBounds();
    }

    /** The parts in the order they were added. */
    public RsBodyPart[] getBodyPartArray() {
        return parts.toArray(new RsBodyPart[0]);
    }

    /** The painters, in part order. */
    public RsBodyPainter[] getBodyPainterArray() {
        return partsOf(RsBodyPainter.class).toArray(new RsBodyPainter[0]);
    }

    /** The sensors, in part order. */
    public RsBodySensor[] getBodySensorArray() {
        return getBodySensors().toArray(new RsBodySensor[0]);
    }

    /**
     * The sensors, in part order, as a list that cannot be changed: for a caller that reads them at
     * every step, which {@link #getBodySensorArray()}'s copy would cost a copy each time.
     */
    public List<RsBodySensor> getBodySensors() {
        List<RsBodySensor> s = sensors;
        if (s == null) {
            s = List.copyOf(partsOf(RsBodySensor.class));
            sensors = s;
        }
        return s;
    }

    /**
     * The parts that collide with walls and decide whether a placement is clear: shapes, circles,
     * all sensors and painters, in part order. Wheel systems, wheels and art are not included.
     */
    public RsBodyShape[] getInteractiveBodyShapeArray() {
        return interactive().clone();
    }

    private RsBodyShape[] interactive() {
        RsBodyShape[] kept = interactive;
        if (kept == null) {
            List<RsBodyShape> shapes = new ArrayList<>();
            for (RsBodyShape s : partsOf(RsBodyShape.class)) {
                if (!(s instanceof RsWheel)) {
                    shapes.add(s);
                }
            }
            kept = shapes.toArray(new RsBodyShape[0]);
            interactive = kept;
        }
        return kept;
    }

    /** Fills {@link #interactiveOutline} for the current motion's start pose. */
    private void placeInteractiveOutline() {
        RsTransform start = motion.transform0;
        RsBodyShape[] shapes = interactive();
        int n = 0;
        for (RsBodyShape s : shapes) {
            RsSegment[] o = s.collisionOutline();
            n += o == null ? 0 : o.length;
        }
        RsSegment[] into = interactiveOutline;
        if (into == null || into.length != n) {
            into = new RsSegment[n];
            for (int i = 0; i < n; i++) {
                into[i] = new RsSegment();
            }
            interactiveOutline = into;
        }
        int at = 0;
        for (RsBodyShape s : shapes) {
            RsSegment[] o = s.collisionOutline();
            for (int i = 0; o != null && i < o.length; i++) {
                start.map2(o[i], into[at++]);
            }
        }
    }

    private RsBodyContactSensor[] contactSensors() {
        RsBodyContactSensor[] kept = contactSensors;
        if (kept == null) {
            kept = partsOf(RsBodyContactSensor.class).toArray(new RsBodyContactSensor[0]);
            contactSensors = kept;
            contactOutlines = new RsSegment[kept.length][];
        }
        return kept;
    }

    private <T extends RsBodyPart> List<T> partsOf(Class<T> type) {
        List<T> list = new ArrayList<>();
        for (RsBodyPart p : parts) {
            if (type.isInstance(p)) {
                list.add(type.cast(p));
            }
        }
        return list;
    }

    /** The body name (null on the client if so constructed; "" after transmission). */
    public String getName() {
        return name;
    }

    /** The first part with exactly this name, looking into wheel systems too; null if none. */
    public RsBodyPart getPartByName(String partName) {
        for (RsBodyPart p : allParts()) {
            if (partName != null && partName.equals(p.getName())) {
                return p;
            }
        }
        return null;
    }

    /** The part with this id, including the wheels of wheel systems; null if none. */
    public RsBodyPart getPartByID(int id) {
        for (RsBodyPart p : allParts()) {
            if (p.getID() == id) {
                return p;
            }
        }
        return null;
    }

    /** Every part, each actuator followed by its sub-parts. */
    List<RsBodyPart> allParts() {
        List<RsBodyPart> all = new ArrayList<>();
        for (RsBodyPart p : parts) {
            all.add(p);
            if (p instanceof RsActuator) {
                for (RsBodyPart sub : ((RsActuator) p).partsArray) {
                    all.add(sub);
                }
            }
        }
        return all;
    }

    /** Copies the changing state (motion, placement, collision, part states) from another copy of this body. */
    public void copyStateData(RsBody source) {
        source.transferStateDataToBody(this);
    }

    /** Copies this body's changing state into {@code target}, a copy of the same body plan. */
    protected void transferStateDataToBody(RsBody target) {
        target.placement = placement;
        target.collision = collision;
        target.motion = copyOf(motion);
        int n = Math.min(parts.size(), target.parts.size());
        for (int i = 0; i < n; i++) {
            target.parts.get(i).copyStateData(parts.get(i));
        }
    }

    private static RsMotion copyOf(RsMotion m) {
        if (m == null) {
            return null;
        }
        try {
            return (RsMotion) m.clone();
        } catch (CloneNotSupportedException e) {
            throw new IllegalStateException("motion cannot be copied", e);
        }
    }

    /** Brings the wheels (encoders, casters) up to the current motion's current time. */
    public void applyMotion() {
        if (wheelSystem != null && motion != null) {
            wheelSystem.applyMotion(motion);
        }
    }

    /** Resets what a placement resets (wheel steering) and the collision flag. */
    public void resetStateData() {
        for (RsBodyPart p : parts) {
            p.resetStateData();
        }
        collision = false;
    }

    /** Sets whether the current motion ends in a collision. */
    public void setCollision(boolean collision) {
        this.collision = collision;
    }

    /** Whether the current motion ends in a collision. */
    public boolean getCollision() {
        return collision;
    }

    /**
     * The position report at {@code simTime}: the analytic pose of the current motion at that time
     * (clamped to the motion; heading in (-pi, pi]) with the velocity and turn rate of that motion,
     * even after it ended (behavior.md section 5.7). All zero before the first placement.
     */
    public RsPositionEvent getPositionEvent(double simTime) {
        if (motion == null) {
            return new RsPositionEvent(simTime, 0.0, 0.0, 0.0, 0.0, 0.0);
        }
        RsTransform pose = motion.getStateAtTime(simTime);
        return new RsPositionEvent(simTime, pose.m13, pose.m23, pose.getTheta(),
                motion.getVelocity(), motion.getTurnRate());
    }

    /**
     * Evaluates every sensor at {@code pose} (target, range and paint sensors; contact sensors do not
     * change here), in part order.
     *
     * @return whether any sensor's state changed (see {@link RsBodySensor#didStateChange()})
     */
    public boolean processSensors(double simTime, RsPlan plan, RsTransform pose) {
        return processSensors(simTime, plan, plan == null ? null : plan.getWallArray(), pose);
    }

    /**
     * As {@link #processSensors(double, RsPlan, RsTransform)}, with {@code walls} blocking range and
     * target sensors instead of the plan's walls (the simulator adds the other robots).
     */
    public boolean processSensors(double simTime, RsPlan plan, RsWall[] walls, RsTransform pose) {
        boolean changed = false;
        List<RsBodySensor> all = getBodySensors();
        for (int i = 0; i < all.size(); i++) {
            if (all.get(i).computeAndSetState(simTime, plan, walls, pose)) {
                changed = true;
            }
        }
        return changed;
    }

    /**
     * Replaces the motion by the one {@code request} produces from the current pose at {@code time}
     * (behavior.md section 5.2), without a collision search.
     */
    public void computeMotion(double time, RsMotionRequest request) {
        motion = wheelSystem != null
                ? wheelSystem.computeMotion(motion, time, request)
                : MotionRequests.motionFor(motion, time, request);
        collision = false;
    }

    /**
     * Starts a requested motion the way the simulator does: {@link #computeMotion(double,
     * RsMotionRequest)}, then the collision search, which cuts the motion before its first contact
     * (or replaces it by a null motion when that is at once) and flags contact sensors.
     */
    public void computeMotion(double time, RsMotionRequest request, RsPlan plan) {
        computeMotion(time, request);
        searchForCollisions(plan);
    }

    /** As {@link #computeMotion(double, RsMotionRequest, RsPlan)}, colliding with {@code walls}. */
    public void computeMotion(double time, RsMotionRequest request, RsWall[] walls) {
        computeMotion(time, request);
        searchForCollisions(walls);
    }

    /** Replaces the current motion as is (no collision search). */
    public void setMotion(RsMotion motion) {
        this.motion = motion;
    }

    /** The current motion, or null before the first placement. */
    public RsMotion getMotion() {
        return motion;
    }

    /**
     * Places the robot at (x, y) heading {@code orientation}: a fresh motion history (a new continuity
     * series), straightened wheels, no collision; sensor, contact and encoder states are kept.
     */
    public void place(double time, double x, double y, double orientation) {
        RsMotion before = motion;
        motion = new RsMotionNull(time, x, y, orientation);
        motion.startSeriesAfter(before);
        resetStateData();
        placement = true;
    }

    /** Draws every part in order at the current pose; {@code view} maps world metres to pixels. */
    public void paint(Graphics g, RsTransform view) {
        RsTransform t = motion == null ? new RsTransform(view) : new RsTransform(view, motion.transform);
        for (RsBodyPart p : parts) {
            p.paint(g, t);
        }
    }

    /** Marks the robot placed (part of the simulation) or not. */
    public void setPlacement(boolean placement) {
        this.placement = placement;
    }

    /** Whether the robot is placed. */
    public boolean getPlacement() {
        return placement;
    }

    /**
     * The collision search for the current motion (behavior.md sections 6.2 and 6.3): contact
     * sensors are flagged first, then every interactive shape is swept over the whole motion; the
     * motion is cut at the last whole millisecond before the first contact, and replaced by a null
     * motion (at the start pose, collision flag clear) when that leaves nothing of it.
     *
     * @return whether a collision was predicted
     */
    protected boolean searchForCollisions(RsPlan plan) {
        return plan != null && searchForCollisions(plan.getWallArray());
    }

    private boolean searchForCollisions(RsWall[] walls) {
        if (motion == null || walls == null) {
            return false;
        }
        boolean placed = walls.length > 0 && motion.transform0.sameBits(outlinesPlacedAt);
        flagContactSensors(walls, placed);
        boolean hit = false;
        // Most turns on the spot have no wall near: nothing to place the outlines for.
        if (walls.length > 0) {
            if (!placed) {
                placeInteractiveOutline();
                outlinesPlacedAt = new RsTransform(motion.transform0);
            }
            RsSegment[] outline = interactiveOutline;
            hit = outline.length > 0
                    && RsBodyPart.searchForCollisions(outline, walls, RsBodyPart.nearestFirst(walls, motion), motion);
        }
        if (motion.collision) {
            motion.truncateForCollision();
            if (motion.timeTotal == 0.0) {
                motion = new RsMotionNull(motion, motion.time0);
            }
        }
        collision = motion.collision;
        return hit;
    }

    /**
     * RP1 0.60's contact-sensor pre-pass (behavior.md section 6.3): the contact sensors, in part order,
     * are swept against every wall, in plan order, over the whole requested motion, all sharing one
     * running minimum of the contact time. A sensor is flagged only when one of its contacts comes
     * strictly earlier than that minimum; it then records the new minimum and the wall that set it.
     * A sensor whose contacts are all later than (or as late as) the minimum so far is not flagged,
     * however real those contacts are. Afterwards a flag recorded before a later sensor lowered the
     * minimum is withdrawn, so only the sensor holding the earliest contact stays flagged. The
     * general search over all parts that follows never re-examines these flags, which is why a
     * sensor can still go hot although the chassis stopped the motion before the sensor touched.
     * {@code placed}: the sensors' outlines are already placed at the motion's start.
     */
    private void flagContactSensors(RsWall[] walls, boolean placed) {
        RsBodyContactSensor[] sensors = contactSensors();
        RsSegment[][] outlines = contactOutlines;
        RsTransform start = motion.transform0;
        double earliest = Double.POSITIVE_INFINITY;
        for (int i = 0; i < sensors.length; i++) {
            RsBodyContactSensor s = sensors[i];
            s.setCollision(false, null);
            s.setCollisionTime(Double.POSITIVE_INFINITY);
            if (walls.length == 0) {
                continue;
            }
            RsSegment[] body = placed ? outlines[i] : BodyOutline.mapInto(s.outline(), start, outlines[i]);
            outlines[i] = body;
            double[] prepared = motion.prepare(body, body.length);
            for (RsWall wall : walls) {
                RsSegment[] edges = wall.getSegmentArray();
                // A wall that can only be met after the earliest contact so far cannot flag a sensor.
                if (earliest < Double.POSITIVE_INFINITY
                        && motion.cannotMeetBefore(body, body.length, edges, edges.length, earliest, prepared)) {
                    continue;
                }
                double t = motion.contactTime(body, body.length, edges, edges.length, prepared);
                if (t < earliest) {
                    earliest = t;
                    s.setCollision(true, wall.getName());
                    s.setCollisionTime(t);
                }
            }
        }
        for (RsBodyContactSensor s : sensors) {
            if (s.getCollision() && s.getCollisionTime() > earliest) {
                s.setCollision(false, null);
            }
        }
    }

    /**
     * Behaviour at the start of a motion (behavior.md section 5.4 step 2e): every hot contact sensor
     * not predicted to be touching at the start of the new motion goes cold.
     *
     * @return one event per released sensor, in part order, carrying the wall name the new motion's
     *         collision search recorded ("" if none)
     */
    public RsContactSensorEvent[] releaseContactSensors(double simTime) {
        List<RsContactSensorEvent> events = null;
        for (RsBodyContactSensor s : contactSensors()) {
            if (s.getHot() && !s.isInContactAtMotionStart()) {
                if (events == null) {
                    events = new ArrayList<>();
                }
                s.setHot(false);
                events.add(s.getStateChangeEvent(simTime));
            }
        }
        return events == null ? NO_CONTACT_EVENTS : events.toArray(NO_CONTACT_EVENTS);
    }

    /**
     * Behaviour at the end of a motion cut short by a collision (section 5.4 step 5a): every flagged
     * contact sensor that is not yet hot goes hot. Nothing happens if the motion had no collision.
     *
     * @return one event per pressed sensor, in part order, with the wall name
     */
    public RsContactSensorEvent[] pressContactSensors(double simTime) {
        if (motion == null || !motion.collision) {
            return NO_CONTACT_EVENTS;
        }
        List<RsContactSensorEvent> events = null;
        for (RsBodyContactSensor s : contactSensors()) {
            if (s.getCollision() && !s.getHot()) {
                if (events == null) {
                    events = new ArrayList<>();
                }
                s.setHot(true);
                events.add(s.getStateChangeEvent(simTime));
            }
        }
        return events == null ? NO_CONTACT_EVENTS : events.toArray(NO_CONTACT_EVENTS);
    }

    /** The bounding box of the body at its current pose, world coordinates. */
    public RsRectangle getBounds() {
        updateRefBounds();
        RsRectangle r = new RsRectangle(refBounds);
        if (motion != null) {
            r.transform(motion.transform);
        }
        return r;
    }

    /** The edges of the body-coordinate bounding box. */
    public RsSegment[] getRefEnclosure() {
        updateRefBounds();
        return BodyOutline.copy(refEnclosure);
    }

    private void updateRefBounds() {
        RsRectangle r = new RsRectangle();
        for (RsBodyPart p : parts) {
            if (p instanceof RsWheelSystem) {
                ((RsWheelSystem) p).computeBounds();
            }
            r.union(p.refBounds);
        }
        refBounds = r;
        double[] corners = BodyOutline.rectanglePoints(r.x + r.width / 2, r.y + r.height / 2, r.width, r.height);
        refEnclosure = r.isPopulated() ? BodyOutline.edgesFromPoints(corners, 4) : new RsSegment[0];
    }

    /**
     * The body's number among the bodies its client has sent (1 for the first), the same on both ends
     * of the session; 0 for a body not sent yet. Bodies are not identified on the wire.
     */
    public int getID() {
        return bodyID;
    }

    /** Numbers the body as the {@code n}-th its client sent. */
    void assignID(int n) {
        bodyID = n;
    }

    /**
     * The placement clear test (behavior.md section 7): whether any interactive shape, with the body
     * at {@code pose}, crosses, lies inside or comes within 1e-4 m of a wall. A body without
     * interactive shapes never overlaps.
     */
    public boolean checkForOverlap(RsPlan plan, RsTransform pose) {
        return plan != null && checkForOverlap(plan.getWallArray(), pose);
    }

    /** As {@link #checkForOverlap(RsPlan, RsTransform)}, against {@code walls}. */
    public boolean checkForOverlap(RsWall[] walls, RsTransform pose) {
        for (RsBodyShape s : interactive()) {
            if (s.checkForOverlap(walls, pose)) {
                return true;
            }
        }
        return false;
    }

    @Override
    public String toString() {
        return "RsBody[" + name + ", " + parts.size() + " parts]";
    }
}
