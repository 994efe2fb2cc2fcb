package rp1.simulator.noise;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import rp1.rossum.RsBody;
import rp1.rossum.RsTransform;
import rp1.rossum.request.RsMotionRequest;

/** Dead reckoning agrees with the motions the simulator makes of the same requests. */
class OdometryTest {
    private static final double EPS = 1e-9;

    private static void agrees(double v, double w, double elapsed) {
        RsBody body = new RsBody("probe");
        body.place(0.0, 1.5, -2.0, 0.7);
        RsMotionRequest r = new RsMotionRequest(v, w, 10.0);
        body.computeMotion(0.0, r);
        RsTransform truth = body.getMotion().getPoseAtTime(elapsed);
        double[] dead = Odometry.after(1.5, -2.0, 0.7, r, elapsed);
        String what = "v " + v + ", w " + w;
        assertEquals(truth.m13, dead[0], EPS, what);
        assertEquals(truth.m23, dead[1], EPS, what);
        assertEquals(0.0, Math.IEEEremainder(truth.getTheta() - dead[2], 2 * Math.PI), EPS, what);
    }

    @Test
    void straightLinesForwardAndBack() {
        agrees(0.3, 0.0, 4.0);
        agrees(-0.3, 0.0, 4.0);
    }

    @Test
    void arcsEitherWayForwardAndBack() {
        agrees(0.3, 0.5, 3.0);
        agrees(0.3, -0.5, 3.0);
        agrees(-0.3, 0.5, 3.0);
        agrees(-0.3, -0.5, 3.0);
    }

    @Test
    void pivotsAndNullMotions() {
        agrees(0.0, 1.2, 2.0);
        agrees(0.0, 0.0, 2.0);
    }
}
