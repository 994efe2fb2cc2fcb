package rp1.simulator.scenario;

import rp1.rossum.RsBody;
import rp1.rossum.RsBodyCircle;
import rp1.rossum.RsBodyContactSensor;
import rp1.rossum.RsBodyPaintSensor;
import rp1.rossum.RsBodyRangeSensor;
import rp1.rossum.RsBodyTargetSensor;
import rp1.rossum.RsDifferentialSteering;

/** Robot bodies for scenario tests, built like the guide's ClientZero. */
final class Bodies {
    /** Radius of the round chassis, metres. */
    static final double RADIUS = 0.15;

    private Bodies() {
    }

    /** A 0.3 m round robot with a differential drive (axle at the centre). */
    static RsBody round(String name) {
        RsBody body = new RsBody(name);
        RsDifferentialSteering drive = new RsDifferentialSteering(0.18, 0.075);
        drive.addDefaultWheels(0.075, 0.03);
        RsBodyCircle chassis = new RsBodyCircle(0.0, 0.0, RADIUS);
        chassis.setName("chassis");
        body.addPart(chassis);
        body.addPart(drive);
        return body;
    }

    /** The round robot with a forward target sensor "head": 90 degrees wide, 2 m, 3 width and 4 range bins. */
    static RsBody withHead(String name) {
        RsBody body = round(name);
        RsBodyTargetSensor head = new RsBodyTargetSensor(box(0.09, 0.16), 4, 0.16, 0.0, 0.0, Math.PI / 2, 2.0, 3, 4);
        head.setName("head");
        body.addPart(head);
        return body;
    }

    /** The round robot with a forward range sensor "sonar": 1 m, 10 bins. */
    static RsBody withSonar(String name) {
        RsBody body = round(name);
        RsBodyRangeSensor sonar = new RsBodyRangeSensor(box(0.09, 0.16), 4, 0.16, 0.0, 0.0, 1.0, 10);
        sonar.setName("sonar");
        body.addPart(sonar);
        return body;
    }

    /** The round robot with a paint sensor "eye" at its centre, sensitive to every region. */
    static RsBody withEye(String name) {
        RsBody body = round(name);
        RsBodyPaintSensor eye = new RsBodyPaintSensor(box(-0.02, 0.02), 4, 0.0, 0.0);
        eye.setName("eye");
        body.addPart(eye);
        return body;
    }

    /** The round robot with a front bumper "bumper" reaching 1 cm beyond the chassis. */
    static RsBody withBumper(String name) {
        RsBody body = round(name);
        RsBodyContactSensor bumper = new RsBodyContactSensor(new double[] {
            0.12, -0.08, 0.16, -0.08, 0.16, 0.08, 0.12, 0.08}, 4);
        bumper.setName("bumper");
        body.addPart(bumper);
        return body;
    }

    /**
     * The bumper robot with a rear contact sensor "tail" added after the bumper, its mirror image:
     * from x = -0.16 to -0.12, 16 cm wide.
     */
    static RsBody withBumperAndTail(String name) {
        RsBody body = withBumper(name);
        RsBodyContactSensor tail = new RsBodyContactSensor(new double[] {
            -0.16, -0.08, -0.12, -0.08, -0.12, 0.08, -0.16, 0.08}, 4);
        tail.setName("tail");
        body.addPart(tail);
        return body;
    }

    /** A small box in front of the centre, from x0 to x1, 5 cm wide. */
    static double[] box(double x0, double x1) {
        return new double[] {x0, -0.025, x1, -0.025, x1, 0.025, x0, 0.025};
    }
}
