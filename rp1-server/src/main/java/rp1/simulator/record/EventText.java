package rp1.simulator.record;

import rp1.rossum.RsPlan;
import rp1.rossum.event.RsContactSensorEvent;
import rp1.rossum.event.RsEncoderStatusEvent;
import rp1.rossum.event.RsEvent;
import rp1.rossum.event.RsHeartbeatEvent;
import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.event.RsMotionStartedEvent;
import rp1.rossum.event.RsMouseClickEvent;
import rp1.rossum.event.RsPaintSensorEvent;
import rp1.rossum.event.RsPlacementEvent;
import rp1.rossum.event.RsPlanEvent;
import rp1.rossum.event.RsPositionEvent;
import rp1.rossum.event.RsRangeSensorEvent;
import rp1.rossum.event.RsTargetSelectionEvent;
import rp1.rossum.event.RsTargetSensorEvent;
import rp1.rossum.event.RsTimeoutEvent;

/**
 * An event as one line of an event log (docs/recording.md): its simulated time, the number of the
 * client it went to, its name (the API class without {@code Rs} and {@code Event}) and its fields as
 * {@code name=value}, named as in the API. The same event always gives the same line.
 */
public final class EventText {
    private EventText() {
    }

    /** The line for {@code event} sent to client {@code client}. */
    public static String line(int client, RsEvent event) {
        TextLine line = new TextLine(Double.toString(event.simTime)).integer(client);
        if (event instanceof RsPositionEvent e) {
            line.word("Position").field("x", e.x).field("y", e.y).field("orientation", e.orientation)
                    .field("velocity", e.velocity).field("turnRate", e.turnRate);
        } else if (event instanceof RsRangeSensorEvent e) {
            line.word("RangeSensor").field("sensorID", e.sensorID).field("status", e.status).field("range", e.range)
                    .field("x", e.x).field("y", e.y).field("ux", e.ux).field("uy", e.uy)
                    .field("nameOfObjectDetected", e.getNameOfObjectDetected());
        } else if (event instanceof RsTargetSensorEvent e) {
            line.word("TargetSensor").field("sensorID", e.sensorID).field("status", e.status)
                    .field("range", e.range).field("bearing", e.bearing)
                    .field("xDetection", e.xDetection).field("yDetection", e.yDetection)
                    .field("x", e.x).field("y", e.y).field("ux", e.ux).field("uy", e.uy)
                    .field("nameOfObjectDetected", e.getNameOfObjectDetected());
        } else if (event instanceof RsContactSensorEvent e) {
            line.word("ContactSensor").field("sensorID", e.sensorID).field("status", e.status)
                    .field("nameOfObjectDetected", e.getNameOfObjectDetected());
        } else if (event instanceof RsPaintSensorEvent e) {
            line.word("PaintSensor").field("sensorID", e.sensorID).field("status", e.status)
                    .field("region", e.region).field("x", e.x).field("y", e.y);
        } else {
            motionOrOther(line, event);
        }
        return line.toString();
    }

    private static void motionOrOther(TextLine line, RsEvent event) {
        if (event instanceof RsMotionStartedEvent e) {
            line.word("MotionStarted").field("linearVelocity", e.linearVelocity)
                    .field("rotationalVelocity", e.rotationalVelocity).field("duration", e.duration)
                    .field("x", e.x).field("y", e.y).field("orientation", e.orientation);
        } else if (event instanceof RsMotionHaltedEvent e) {
            line.word("MotionHalted").field("causeOfHalt", e.causeOfHalt).field("x", e.x).field("y", e.y)
                    .field("orientation", e.orientation).field("duration", e.duration);
        } else if (event instanceof RsPlacementEvent e) {
            line.word("Placement").field("valid", e.valid).field("name", e.name).field("x", e.x).field("y", e.y)
                    .field("orientation", e.orientation);
        } else if (event instanceof RsEncoderStatusEvent e) {
            line.word("EncoderStatus").field("requestIndex", e.requestIndex).field("encoderID", e.encoderID)
                    .field("accumulatorValue", e.accumulatorValue)
                    .field("absoluteAccumulatorValue", e.absoluteAccumulatorValue)
                    .field("quadratureValue", e.quadratureValue).field("encoderInterval", e.encoderInterval)
                    .field("encoderAngle", e.encoderAngle).field("clearOnReport", e.clearOnReport);
        } else {
            simple(line, event);
        }
    }

    private static void simple(TextLine line, RsEvent event) {
        if (event instanceof RsTimeoutEvent e) {
            line.word("Timeout").field("timeoutIndex", e.timeoutIndex);
        } else if (event instanceof RsHeartbeatEvent e) {
            line.word("Heartbeat").field("sequence", e.sequence);
        } else if (event instanceof RsMouseClickEvent e) {
            line.word("MouseClick").field("button", e.button).field("clickCount", e.clickCount)
                    .field("x", e.x).field("y", e.y);
        } else if (event instanceof RsTargetSelectionEvent e) {
            line.word("TargetSelection").field("targetName", e.targetName).field("status", e.status);
        } else if (event instanceof RsPlanEvent e) {
            RsPlan plan = e.plan instanceof RsPlan p ? p : null;
            line.word("Plan").field("caption", plan == null ? null : plan.getCaption())
                    .field("objects", plan == null ? 0 : plan.getObjectCount());
        } else {
            line.word(event.getClass().getSimpleName()).field("eventID", event.eventID);
        }
    }
}
