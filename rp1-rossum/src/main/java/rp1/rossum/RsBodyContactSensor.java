package rp1.rossum;

import rp1.rossum.event.RsContactSensorEvent;
import rp1.rossum.event.RsSensorEvent;

/**
 * A bumper: a shape that reports physical contact with walls. It is not evaluated at motion steps;
 * its state changes only when a motion starts (pressure released, unless the new motion is predicted
 * to be in contact from its start) and when a motion ends in a collision that the collision search
 * attributed to it (behavior.md sections 6.3 and 8.5).
 */
public class RsBodyContactSensor extends RsBodySensor {
    private static final long serialVersionUID = 1L;

    /** Whether the collision search of the current motion flagged this sensor. */
    protected boolean collision;
    /** The contact time recorded by that search, seconds after the motion's start. */
    protected double collisionTime;
    /** The wall recorded by that search, or null. */
    protected String collisionObjectName;

    /** A contact sensor with the given outline (see {@link RsBodyShape#RsBodyShape(double[], int)}). */
    public RsBodyContactSensor(double[] point, int nPoint) {
        super(point, nPoint);
        name = "Unnamed Contact Sensor";
    }

    /** Contact sensors do not change at motion steps: always false, nothing changes. */
    @Override
    public boolean computeAndSetState(double simTime, RsPlan plan, RsTransform pose) {
        return recordEvaluation(simTime, false);
    }

    /** Sets the collision flag; the recorded wall name is kept. */
    public void setCollision(boolean collision) {
        this.collision = collision;
    }

    /** Sets the collision flag and the name of the wall involved. */
    public void setCollision(boolean collision, String objectName) {
        this.collision = collision;
        this.collisionObjectName = objectName;
    }

    /** Records the contact time found by the collision search (seconds after the motion start). */
    public void setCollisionTime(double time) {
        collisionTime = time;
    }

    /** Whether the collision search of the current motion flagged this sensor. */
    public boolean getCollision() {
        return collision;
    }

    /** The contact time recorded by the collision search, seconds after the motion start. */
    public double getCollisionTime() {
        return collisionTime;
    }

    /** The wall recorded by the last collision search, or null. */
    public String getCollisionObjectName() {
        return collisionObjectName;
    }

    /**
     * Whether the collision search predicts this sensor to be touching at the very start of the
     * motion: flagged, with a contact so soon that the motion is cut at time 0.
     */
    public boolean isInContactAtMotionStart() {
        return collision && RsMotion.stopTimeForContact(collisionTime) == 0.0;
    }

    /** The state as a contact-sensor event (hot = in contact). A polled state carries no wall name. */
    @Override
    public RsSensorEvent getSensorEvent(double simTime) {
        return new RsContactSensorEvent(simTime, getID(), hot, "");
    }

    /** The event for a state change: the current state with the recorded wall name ("" if none). */
    public RsContactSensorEvent getStateChangeEvent(double simTime) {
        return new RsContactSensorEvent(simTime, getID(), hot, nameOrEmpty(collisionObjectName));
    }

    /** Sends this sensor's state change (with the contacted wall's name) to a client connection. */
    public void sendSensorEvent(RsConnection connection, double simTime) {
        connection.sendContactSensorEvent(getStateChangeEvent(simTime));
    }
}
