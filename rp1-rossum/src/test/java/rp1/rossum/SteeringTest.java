package rp1.rossum;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import org.junit.jupiter.api.Test;
import rp1.rossum.request.RsActuatorControlRequest;
import rp1.rossum.request.RsMotionRequest;

/** Differential and Ackerman steering: derivations, conversions and control requests. */
class SteeringTest {
    private static final double EPS = 1e-12;

    @Test
    void differentialRequestFromWheelVelocitiesIsTheirMeanAndDifference() {
        RsDifferentialSteering d = new RsDifferentialSteering(0.5, 0.1);
        RsMotionRequest r = d.getMotionRequestUsingWheelVelocities(0.4, 0.6, 3.0);
        assertEquals(0.5, r.linearVelocity, EPS);
        assertEquals(0.4, r.rotationalVelocity, EPS);
        assertEquals(3.0, r.duration);
    }

    @Test
    void differentialRequestFromWheelRotationUsesTheDriveWheelRadius() {
        RsDifferentialSteering d = new RsDifferentialSteering(0.5, 0.1);
        RsMotionRequest r = d.getMotionRequestUsingWheelRotationalVelocities(4.0, 6.0, 1.0);
        assertEquals(0.5, r.linearVelocity, EPS);
        assertEquals(0.4, r.rotationalVelocity, EPS);
    }

    @Test
    void differentialControlRequestNamesBothWheelsInOrder() {
        RsDifferentialSteering d = new RsDifferentialSteering(0.5, 0.1);
        RsActuatorControlRequest r = d.getControlRequestForWheelRotation(1.5, -2.0);
        assertEquals(d.getID(), r.actuatorID);
        assertEquals(RsActuatorControlRequest.ACTIVATE, r.commandID);
        assertArrayEquals(new String[] {"leftRotationalVelocity", "rightRotationalVelocity"}, r.getParameterNames());
        assertArrayEquals(new double[] {1.5, -2.0}, r.getParameterValues());
    }

    @Test
    void differentialControlRequestForStillWheelsIsAParameterlessHalt() {
        RsDifferentialSteering d = new RsDifferentialSteering(0.5, 0.1);
        RsActuatorControlRequest r = d.getControlRequestForWheelRotation(0.0, 0.0);
        assertEquals(RsActuatorControlRequest.HALT, r.commandID);
        assertEquals(0, r.getParameterNames().length);
    }

    @Test
    void differentialActuatorControlRunsFor300000Seconds() {
        RsDifferentialSteering d = new RsDifferentialSteering(0.5, 0.1);
        RsMotionRequest r = d.getMotionRequestForActuatorControl(new double[] {10.0, 20.0});
        assertEquals(1.5, r.linearVelocity, EPS);
        assertEquals(2.0, r.rotationalVelocity, EPS);
        assertEquals(300000.0, r.duration);
        assertNull(d.getMotionRequestForActuatorControl(new double[] {1.0}));
    }

    @Test
    void ackermanMinimumTurnRadiusAndCentralLimitFollowFromTheInnerLimit() {
        RsAckermanSteering a = new RsAckermanSteering(0.5, 1.0, 0.1, Math.toRadians(45), false);
        assertEquals(1.25, a.getMinTurnRadius(), EPS);
        assertEquals(Math.atan(0.8), a.getMaxAbsSteeringAngle(), EPS);
    }

    @Test
    void dualSteeringHalvesTheSteeringBase() {
        RsAckermanSteering a = new RsAckermanSteering(0.5, 1.0, 0.1, Math.toRadians(45), true);
        assertEquals(0.75, a.getMinTurnRadius(), EPS);
        assertEquals(Math.atan(0.5 / 0.75), a.getMaxAbsSteeringAngle(), EPS);
    }

    @Test
    void theInnerWheelLimitIsCappedAt85Degrees() {
        RsAckermanSteering a = new RsAckermanSteering(0.5, 1.0, 0.1, Math.toRadians(89), false);
        assertEquals(1.0 / Math.tan(Math.toRadians(85)) + 0.25, a.getMinTurnRadius(), EPS);
    }

    @Test
    void turnRadiusForASteeringAngleIsLimitedByTheCentralLimit() {
        RsAckermanSteering a = new RsAckermanSteering(0.5, 1.0, 0.1, Math.toRadians(45), false);
        assertEquals(1.0 / Math.tan(0.3), a.getTurnRadiusForSteeringAngle(0.3), EPS);
        assertEquals(1.25, a.getTurnRadiusForSteeringAngle(1.2), 1e-9);
        assertEquals(-1.25, a.getTurnRadiusForSteeringAngle(-1.2), 1e-9);
        assertEquals(Double.POSITIVE_INFINITY, a.getTurnRadiusForSteeringAngle(0.0));
    }

    @Test
    void ackermanVelocityConversions() {
        RsAckermanSteering a = new RsAckermanSteering(0.5, 1.0, 0.1, Math.toRadians(45), false);
        assertEquals(10.0, a.mapVelocityToWheelRotationalVelocity(1.0), EPS);
        assertEquals(60.0 / (2 * Math.PI * 0.1), a.mapVelocityToWheelRPM(1.0), EPS);
        assertEquals(1.0, a.mapWheelRPMToVelocity(a.mapVelocityToWheelRPM(1.0)), EPS);
    }

    @Test
    void ackermanRequestTurnsAtVelocityOverTurnRadius() {
        RsAckermanSteering a = new RsAckermanSteering(0.5, 1.0, 0.1, Math.toRadians(45), false);
        RsMotionRequest r = a.getMotionRequestUsingVelocityAndSteeringAngle(2.0, 0.3, 4.0);
        assertEquals(2.0, r.linearVelocity);
        assertEquals(2.0 * Math.tan(0.3), r.rotationalVelocity, EPS);
        assertEquals(0.0, a.getMotionRequestUsingVelocityAndSteeringAngle(2.0, 1e-5, 4.0).rotationalVelocity);
        RsMotionRequest w = a.getMotionRequestUsingWheelRotationalVelocityAndSteeringAngle(20.0, 0.3, 4.0);
        assertEquals(2.0, w.linearVelocity, EPS);
    }

    @Test
    void ackermanControlRequestNamesDriveAndSteering() {
        RsAckermanSteering a = new RsAckermanSteering(0.5, 1.0, 0.1, Math.toRadians(45), false);
        RsActuatorControlRequest r = a.getControlRequestForWheelRotationAndSteeringAngle(3.0, 0.2);
        assertEquals(a.getID(), r.actuatorID);
        assertEquals(RsActuatorControlRequest.ACTIVATE, r.commandID);
        assertArrayEquals(new String[] {"driveRotationalVelocity", "steeringAngle"}, r.getParameterNames());
        assertArrayEquals(new double[] {3.0, 0.2}, r.getParameterValues());
    }

    @Test
    void ackermanActuatorControlSteersThenDrives() {
        RsAckermanSteering a = new RsAckermanSteering(0.5, 1.0, 0.1, Math.toRadians(45), false);
        RsMotionRequest r = a.getMotionRequestForActuatorControl(new double[] {10.0, 0.2});
        assertEquals(1.0, r.linearVelocity, EPS);
        assertEquals(Math.tan(0.2), r.rotationalVelocity, EPS);
        assertEquals(0.2, a.getSteeringAngle(), EPS);
        RsMotionRequest limited = a.getMotionRequestForActuatorControl(new double[] {10.0, 1.5});
        assertEquals(0.8, limited.rotationalVelocity, 1e-9);
    }

    @Test
    void atFullLockTheInnerFrontWheelReachesTheInnerWheelLimitAndTheRearWheelsStayStraight() {
        RsAckermanSteering a = new RsAckermanSteering(0.5, 1.0, 0.1, Math.toRadians(45), false);
        a.addDefaultWheels(0.1, 0.05, 0.1, 0.02);
        a.setSteeringAngle(a.getMaxAbsSteeringAngle());
        RsWheel[] w = a.getWheels();
        assertEquals(Math.toRadians(45), w[2].getSteeringAngle(), 1e-9, "front left, the inner wheel of a left turn");
        assertEquals(Math.atan2(1.0, 1.5), w[3].getSteeringAngle(), 1e-9);
        assertEquals(0.0, w[0].getSteeringAngle(), "steerable, but on the rear axle (x = 0) it never turns");
        assertEquals(0.0, w[1].getSteeringAngle());
    }

    @Test
    void ackermanDefaultWheelsAreFourUnnamedWheelsSteerableUpToTheCentralLimitRearLeftFirst() {
        RsAckermanSteering a = new RsAckermanSteering(0.5, 1.0, 0.1, Math.toRadians(45), false);
        a.addDefaultWheels(0.1, 0.05, 0.1, 0.02);
        RsWheel[] w = a.getWheels();
        assertEquals(4, w.length);
        double[][] hubs = {{0.0, 0.25}, {0.0, -0.25}, {1.0, 0.25}, {1.0, -0.25}};
        for (int k = 0; k < 4; k++) {
            assertEquals(hubs[k][0], w[k].getX(), "wheel " + k);
            assertEquals(hubs[k][1], w[k].getY(), "wheel " + k);
            assertEquals("Unnamed", w[k].getName());
            assertEquals(true, w[k].isWheelSteerable(), "wheel " + k);
            assertEquals(a.getMaxAbsSteeringAngle(), w[k].getMaxAbsSteeringAngle(), "the derived central limit, atan(0.8)");
            assertEquals(a.getID() + 1 + k, w[k].getID());
        }
    }

    @Test
    void dualSteeringWheelsAreHalfAWheelBaseEitherSideAndTurnOppositeWays() {
        RsAckermanSteering a = new RsAckermanSteering(0.5, 1.0, 0.1, Math.toRadians(45), true);
        a.addDefaultWheels(0.1, 0.05, 0.1, 0.02);
        a.setSteeringAngle(0.3);
        RsWheel[] w = a.getWheels();
        assertEquals(-0.5, w[0].getX());
        assertEquals(0.5, w[2].getX());
        assertEquals(-w[2].getSteeringAngle(), w[0].getSteeringAngle(), 1e-12);
    }

    @Test
    void aPlacementStraightensTheSteering() {
        RsAckermanSteering a = new RsAckermanSteering(0.5, 1.0, 0.1, Math.toRadians(45), false);
        a.addDefaultWheels(0.1, 0.05, 0.1, 0.02);
        a.setSteeringAngle(0.3);
        a.resetStateData();
        assertEquals(0.0, a.getSteeringAngle());
        assertEquals(0.0, a.getWheels()[2].getSteeringAngle());
    }
}
