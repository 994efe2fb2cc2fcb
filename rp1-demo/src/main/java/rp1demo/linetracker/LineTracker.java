package rp1demo.linetracker;

import java.awt.Color;

import rp1.rossum.RsBody;
import rp1.rossum.RsBodyCircle;
import rp1.rossum.RsBodyPaintSensor;
import rp1.rossum.RsDifferentialSteering;

/**
 * The line tracker's body: a round robot 10 cm across on two wheels, with two paint sensors
 * ("left eye", "right eye") 5 cm ahead of the axle, 1 cm apart. The line of linetrack.txt is 2 cm
 * wide, so on the middle of the line both eyes see it; drifting to one side takes that side's eye off.
 * The eyes respond only to paint of region {@value #LINE_REGION}, the line's.
 */
public final class LineTracker {
    /** Region code of the line's paint in linetrack.txt. */
    public static final int LINE_REGION = 1;
    public static final String LEFT_EYE = "left eye";
    public static final String RIGHT_EYE = "right eye";
    /** Distance between the wheels, metres. */
    public static final double TRACK_WIDTH = 0.08;
    /** How far ahead of the axle the eyes are, metres. */
    public static final double EYE_X = 0.05;
    /** How far each eye is from the robot's centre line, metres. */
    public static final double EYE_Y = 0.005;

    private LineTracker() {
    }

    /** A new line-tracker body; the wheels are added last so that they are drawn on top. */
    public static RsBody build() {
        RsBody body = new RsBody("LineTracker");
        double wheelRadius = 0.02;
        RsDifferentialSteering wheels = new RsDifferentialSteering(TRACK_WIDTH, wheelRadius);
        wheels.addDefaultWheels(wheelRadius, 0.01);
        wheels.setFillColor(Color.darkGray);
        wheels.setLineColor(Color.darkGray);

        RsBodyCircle chassis = new RsBodyCircle(0.0, 0.0, 0.05);
        chassis.setName("chassis");
        chassis.setFillColor(Color.yellow);
        chassis.setLineColor(Color.darkGray);
        body.addPart(chassis);
        body.addPart(eye(LEFT_EYE, EYE_Y));
        body.addPart(eye(RIGHT_EYE, -EYE_Y));
        body.addPart(wheels);
        return body;
    }

    /** A paint sensor with its detector at (EYE_X, y), drawn as a 4 mm square around it. */
    private static RsBodyPaintSensor eye(String name, double y) {
        double h = 0.002;
        double[] outline = {
            EYE_X - h, y - h,
            EYE_X + h, y - h,
            EYE_X + h, y + h,
            EYE_X - h, y + h};
        RsBodyPaintSensor eye = new RsBodyPaintSensor(outline, 4, EYE_X, y);
        eye.setName(name);
        eye.setRegionSensitivity(LINE_REGION);
        eye.setFillColor(Color.gray);
        eye.setLineColor(Color.gray);
        eye.setHotFillColor(Color.green);
        eye.setHotLineColor(Color.green);
        return eye;
    }
}
