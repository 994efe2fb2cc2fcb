package rp1.rossum;

import java.awt.Color;
import java.awt.Graphics;
import java.util.ArrayList;
import rp1.rossum.request.RsMotionRequest;

/**
 * The locomotion system of a robot: its geometry (track width, wheel base, drive-wheel radius), its
 * wheels (drawn, with optional encoders) and the arithmetic from goals or wheel speeds to motion
 * requests. The axle is centred on the body origin and runs along the body's y axis. Concrete
 * systems are {@link RsDifferentialSteering} and {@link RsAckermanSteering}. A wheel system's part id
 * identifies it in actuator-control requests; its wheels take the following ids when built right
 * after it.
 */
public abstract class RsWheelSystem extends RsActuator {
    private static final long serialVersionUID = 1L;

    /** Duration of the motion an actuator-control request starts, seconds ("until further notice"). */
    static final double CONTROL_DURATION = 300000.0;

    /** Distance between the left and right wheels, metres. */
    protected double trackWidth;
    /** Distance between the rear and front axles, metres (0 for a differential drive). */
    protected double wheelBase;
    /** Radius of the drive wheels, metres. */
    protected double driveWheelRadius;
    /** The wheels, in the order added (a copy of {@link #wheelList}). */
    protected RsWheel[] wheels = new RsWheel[0];
    /** The wheels, in the order added. */
    protected ArrayList<RsWheel> wheelList = new ArrayList<>();
    /** Centre of the axle, body coordinates (the body origin). */
    protected RsPoint center = new RsPoint();

    /** A wheel system without wheels, named "Wheel System". */
    public RsWheelSystem() {
        name = "Wheel System";
    }

    /**
     * Adds a wheel for drawing and encoders. For the simulator to give it the same id, build it
     * right after the wheel system and the wheels added before it.
     *
     * @throws IllegalArgumentException if wheel is null
     */
    public void addWheel(RsWheel wheel) {
        if (wheel == null) {
            throw new IllegalArgumentException("wheel is null");
        }
        wheelList.add(wheel);
        wheels = wheelList.toArray(new RsWheel[0]);
        addSubPart(wheel);
        computeBounds();
    }

    /**
     * Adds a pair of fixed wheels on the axle at y = +trackWidth/2 ("left wheel", built first) and
     * y = -trackWidth/2 ("right wheel"), each drawn as a wheelRadius*2 by wheelWidth rectangle.
     */
    public void addDefaultWheels(double wheelRadius, double wheelWidth) {
        addAxleWheels(0.0, wheelRadius, wheelWidth, "left wheel", "right wheel");
    }

    /** Builds, names and adds a fixed left/right pair at x; returns {left, right}. */
    final RsWheel[] addAxleWheels(double x, double wheelRadius, double wheelWidth, String leftName, String rightName) {
        double y = trackWidth / 2.0;
        double length = 2 * wheelRadius;
        RsWheel left = new RsWheel(BodyOutline.rectanglePoints(x, y, length, wheelWidth), 4, x, y, wheelRadius);
        RsWheel right = new RsWheel(BodyOutline.rectanglePoints(x, -y, length, wheelWidth), 4, x, -y, wheelRadius);
        left.setName(leftName);
        right.setName(rightName);
        addWheel(left);
        addWheel(right);
        return new RsWheel[] {left, right};
    }

    /** Distance between the left and right wheels, metres. */
    public double getTrackWidth() {
        return trackWidth;
    }

    /** Distance between the front and rear axles, metres (0 for differential steering). */
    public double getWheelBase() {
        return wheelBase;
    }

    /** Radius of the driven wheels, metres. */
    public double getDriveWheelRadius() {
        return driveWheelRadius;
    }

    /** Sets {@link #refBounds} to the union of the wheels' bounds. */
    protected void computeBounds() {
        RsRectangle r = new RsRectangle();
        for (RsWheel w : wheels) {
            r.union(w.refBounds);
        }
        refBounds = r;
    }

    /** Sets the fill colour of the system and of every wheel added so far. */
    @Override
    public void setFillColor(Color color) {
        super.setFillColor(color);
        for (RsWheel w : wheels) {
            w.setFillColor(color);
        }
    }

    /** Sets the line colour of the system and of every wheel added so far. */
    @Override
    public void setLineColor(Color color) {
        super.setLineColor(color);
        for (RsWheel w : wheels) {
            w.setLineColor(color);
        }
    }

    /** Draws the wheels, in the order they were added. */
    @Override
    public void paint(Graphics g, RsTransform t) {
        for (RsWheel w : wheels) {
            w.paint(g, t);
        }
    }

    /** Brings the wheels (encoders, casters) up to the motion's current time. */
    public void applyMotion(RsMotion motion) {
        for (RsWheel w : wheels) {
            w.applyMotion(motion);
        }
    }

    /**
     * The motion a request produces when it starts at {@code time} from where {@code previous} is then
     * (behavior.md section 5.2). The simulator executes any request, whatever the wheel system.
     */
    public RsMotion computeMotion(RsMotion previous, double time, RsMotionRequest request) {
        return MotionRequests.motionFor(previous, time, request);
    }

    /**
     * A request that takes the robot to the goal (x, y), given in robot coordinates (metres, x
     * forward), at {@code speed} m/s measured at the body origin: a straight line or the arc tangent
     * to the heading that passes through the goal, backing along it when the goal is behind. Null if
     * the goal is too close or the speed too small (behavior.md section 5.6).
     */
    public RsMotionRequest getMotionRequest(double x, double y, double speed) {
        return MotionRequests.towards(x, y, speed);
    }

    /**
     * A request that turns the robot in place to face (x, y) (robot coordinates). The speed is ignored,
     * as in RP1 0.60: pivots turn at pi/2 rad/s. Null if the turn would take less than 1 ms.
     */
    public RsMotionRequest getMotionRequestForPivot(double x, double y, double speed) {
        return MotionRequests.pivotTowards(x, y);
    }

    /**
     * The motion request the simulator starts for an actuator-control request with these parameter
     * values (by position; behavior.md section 5.5), or null when fewer than two values are given.
     */
    public abstract RsMotionRequest getMotionRequestForActuatorControl(double[] values);

    /** A placement straightens the wheels; encoders keep their counts. */
    @Override
    public void resetStateData() {
        for (RsWheel w : wheels) {
            w.resetStateData();
        }
    }

    /** Copies the state of the wheels, wheel by wheel, from another copy of this wheel system. */
    @Override
    public void copyStateData(RsBodyPart source) {
        super.copyStateData(source);
        if (source instanceof RsWheelSystem) {
            RsWheel[] other = ((RsWheelSystem) source).wheels;
            for (int i = 0; i < Math.min(wheels.length, other.length); i++) {
                wheels[i].copyStateData(other[i]);
            }
        }
    }

    /**
     * Adds a caster whose pivot is at (x, y) (body coordinates), drawn as a wheelRadius*2 by wheelWidth
     * rectangle centred on the pivot.
     */
    public void addDefaultCasterWheel(double x, double y, double wheelRadius, double wheelWidth) {
        double[] outline = BodyOutline.rectanglePoints(x, y, 2 * wheelRadius, wheelWidth);
        RsWheelCaster caster = new RsWheelCaster(outline, 4, x, y);
        caster.setName("caster wheel");
        addWheel(caster);
    }

    /** The wheel with this part (encoder) id, or null. */
    public RsWheel getWheelForID(int id) {
        for (RsWheel w : wheels) {
            if (w.getID() == id) {
                return w;
            }
        }
        return null;
    }

    /** The wheels, in the order they were added. */
    public RsWheel[] getWheels() {
        return wheels.clone();
    }
}
