package guidestyle;

import java.awt.Color;

import rp1.rossum.RsBody;
import rp1.rossum.RsBodyCircle;
import rp1.rossum.RsBodySensor;
import rp1.rossum.RsBodyTargetSensor;
import rp1.rossum.RsDifferentialSteering;

/**
 * A body plan written the way the user's guide writes ClientZero.build(): a static method that
 * builds a round robot with a differential drive and a forward-looking target sensor named "head".
 * Its only job in the tests is to prove that such code compiles and works unchanged.
 */
public final class Chassis {
    private Chassis() {
    }

    public static RsBody build() {
        RsBody body = new RsBody("GuideStyle");
        double trackWidth = 0.18;
        double driveWheelRadius = 0.075;
        RsDifferentialSteering wheelSystem = new RsDifferentialSteering(trackWidth, driveWheelRadius);
        wheelSystem.addDefaultWheels(driveWheelRadius, 0.03);
        wheelSystem.setFillColor(Color.darkGray);
        wheelSystem.setLineColor(Color.darkGray);

        RsBodyCircle chassis = new RsBodyCircle(0.0, 0.0, 0.15);
        chassis.setName("main chassis");
        chassis.setFillColor(Color.lightGray);
        chassis.setLineColor(Color.darkGray);
        body.addPart(chassis);

        double[] d1 = {
            0.09, -0.025,
            0.16, -0.025,
            0.16, 0.025,
            0.09, 0.025
        };
        RsBodySensor s1 = new RsBodyTargetSensor(d1, 4, 0.16, 0.0, 0.0, 45 * Math.PI / 180.0, 1.0, 3, 3);
        s1.setName("head");
        s1.setFillColor(Color.blue);
        s1.setLineColor(Color.blue);
        body.addPart(s1);
        body.addPart(wheelSystem);
        return body;
    }
}
