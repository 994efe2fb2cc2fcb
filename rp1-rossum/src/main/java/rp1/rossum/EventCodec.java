package rp1.rossum;

import java.io.IOException;

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
import rp1.rossum.event.RsSensorEvent;
import rp1.rossum.event.RsTargetSelectionEvent;
import rp1.rossum.event.RsTargetSensorEvent;
import rp1.rossum.event.RsTimeoutEvent;
import rp1.rossum.wire.WireIn;
import rp1.rossum.wire.WireOut;

/**
 * Encodes and decodes the body of an EVENT transaction (protocol.md section 7): event code, index,
 * simulation time, interlock value, then the event's fields in wire order (which is not always the
 * constructor order). Works on in-memory buffers; no sockets involved.
 */
final class EventCodec {
    private EventCodec() {
    }

    /** An event read from the wire together with the interlock value it carried. */
    static final class Decoded {
        final RsEvent event;
        final int interlock;

        Decoded(RsEvent event, int interlock) {
            this.event = event;
            this.interlock = interlock;
        }
    }

    /**
     * Writes everything after the header. The index is the sensor id for sensor events and 0 for all
     * others, which is what the client dispatches on.
     */
    static void encode(WireOut out, RsEvent e, int interlock) {
        out.i32(e.eventID).i32(indexOf(e)).f64(e.simTime).i32(interlock);
        switch (e.eventID) {
            case RsEvent.EVT_CONTACT_SENSOR: {
                RsContactSensorEvent c = (RsContactSensorEvent) e;
                out.bool(c.status).str(c.getNameOfObjectDetected());
                break;
            }
            case RsEvent.EVT_MOUSE_CLICK: {
                RsMouseClickEvent m = (RsMouseClickEvent) e;
                out.i32(m.button).i32(m.clickCount).f64(m.x).f64(m.y);
                break;
            }
            case RsEvent.EVT_POSITION: {
                RsPositionEvent p = (RsPositionEvent) e;
                out.f64(p.x).f64(p.y).f64(p.orientation).f64(p.velocity).f64(p.turnRate);
                break;
            }
            case RsEvent.EVT_RANGE_SENSOR: {
                RsRangeSensorEvent r = (RsRangeSensorEvent) e;
                out.f64(r.x).f64(r.y).bool(r.status).f64(r.ux).f64(r.uy).f64(r.range).str(r.getNameOfObjectDetected());
                break;
            }
            case RsEvent.EVT_TARGET_SENSOR: {
                RsTargetSensorEvent t = (RsTargetSensorEvent) e;
                out.f64(t.x).f64(t.y).bool(t.status).f64(t.ux).f64(t.uy).f64(t.xDetection).f64(t.yDetection)
                        .f64(t.range).f64(t.bearing).str(t.getNameOfObjectDetected());
                break;
            }
            case RsEvent.EVT_TIMEOUT:
                out.i32(((RsTimeoutEvent) e).timeoutIndex);
                break;
            case RsEvent.EVT_MOTION_STARTED: {
                RsMotionStartedEvent s = (RsMotionStartedEvent) e;
                out.f64(s.linearVelocity).f64(s.rotationalVelocity).f64(s.duration).f64(s.x).f64(s.y).f64(s.orientation);
                break;
            }
            case RsEvent.EVT_MOTION_HALTED: {
                RsMotionHaltedEvent h = (RsMotionHaltedEvent) e;
                out.i32(h.causeOfHalt).f64(h.x).f64(h.y).f64(h.orientation).f64(h.duration);
                break;
            }
            case RsEvent.EVT_PLACEMENT: {
                RsPlacementEvent p = (RsPlacementEvent) e;
                out.bool(p.valid).str(p.name).f64(p.x).f64(p.y).f64(p.orientation);
                break;
            }
            case RsEvent.EVT_TARGET_SELECTION: {
                RsTargetSelectionEvent t = (RsTargetSelectionEvent) e;
                out.bool(t.status).str(t.targetName);
                break;
            }
            case RsEvent.EVT_PLAN:
                PlanCodec.encode(out, (RsPlan) ((RsPlanEvent) e).plan);
                break;
            case RsEvent.EVT_PAINT_SENSOR: {
                RsPaintSensorEvent p = (RsPaintSensorEvent) e;
                out.f64(p.x).f64(p.y).bool(p.status).i32(p.region);
                break;
            }
            case RsEvent.EVT_HEARTBEAT:
                out.i32(((RsHeartbeatEvent) e).sequence);
                break;
            case RsEvent.EVT_ENCODER_STATUS: {
                RsEncoderStatusEvent s = (RsEncoderStatusEvent) e;
                out.i32(s.requestIndex).i32(s.encoderID).i32(s.accumulatorValue).i32(s.absoluteAccumulatorValue)
                        .i32(s.quadratureValue).i32(s.encoderInterval).f64(s.encoderAngle).bool(s.clearOnReport);
                break;
            }
            default:
                throw new IllegalArgumentException("unknown event code " + e.eventID + " in " + e);
        }
    }

    /**
     * What a client would decode from {@code e} on the wire, built without encoding it: a new event
     * with the same fields, strings that were null as "" (the wire cannot carry null), and for a plan
     * event the plan as the wire delivers it (a decoded copy, without what the wire leaves out).
     */
    static RsEvent copy(RsEvent e) {
        double t = e.simTime;
        switch (e.eventID) {
            case RsEvent.EVT_CONTACT_SENSOR: {
                RsContactSensorEvent c = (RsContactSensorEvent) e;
                return new RsContactSensorEvent(t, c.sensorID, c.status, text(c.getNameOfObjectDetected()));
            }
            case RsEvent.EVT_MOUSE_CLICK: {
                RsMouseClickEvent m = (RsMouseClickEvent) e;
                return new RsMouseClickEvent(t, m.button, m.clickCount, m.x, m.y);
            }
            case RsEvent.EVT_POSITION: {
                RsPositionEvent p = (RsPositionEvent) e;
                return new RsPositionEvent(t, p.x, p.y, p.orientation, p.velocity, p.turnRate);
            }
            case RsEvent.EVT_RANGE_SENSOR: {
                RsRangeSensorEvent r = (RsRangeSensorEvent) e;
                return new RsRangeSensorEvent(t, r.sensorID, r.x, r.y, r.ux, r.uy, r.status, r.range,
                        text(r.getNameOfObjectDetected()));
            }
            case RsEvent.EVT_TARGET_SENSOR: {
                RsTargetSensorEvent s = (RsTargetSensorEvent) e;
                return new RsTargetSensorEvent(t, s.sensorID, s.x, s.y, s.ux, s.uy, s.status, s.xDetection,
                        s.yDetection, s.range, s.bearing, text(s.getNameOfObjectDetected()));
            }
            case RsEvent.EVT_TIMEOUT:
                return new RsTimeoutEvent(t, ((RsTimeoutEvent) e).timeoutIndex);
            case RsEvent.EVT_MOTION_STARTED: {
                RsMotionStartedEvent m = (RsMotionStartedEvent) e;
                return new RsMotionStartedEvent(t, m.linearVelocity, m.rotationalVelocity, m.duration, m.x, m.y,
                        m.orientation);
            }
            case RsEvent.EVT_MOTION_HALTED: {
                RsMotionHaltedEvent h = (RsMotionHaltedEvent) e;
                return new RsMotionHaltedEvent(t, h.causeOfHalt, h.x, h.y, h.orientation, h.duration);
            }
            case RsEvent.EVT_PLACEMENT: {
                RsPlacementEvent p = (RsPlacementEvent) e;
                return new RsPlacementEvent(t, p.valid, text(p.name), p.x, p.y, p.orientation);
            }
            case RsEvent.EVT_TARGET_SELECTION: {
                RsTargetSelectionEvent s = (RsTargetSelectionEvent) e;
                return new RsTargetSelectionEvent(t, text(s.targetName), s.status);
            }
            case RsEvent.EVT_PLAN:
                return new RsPlanEvent(t, PlanCodec.copy((RsPlan) ((RsPlanEvent) e).plan));
            case RsEvent.EVT_PAINT_SENSOR: {
                RsPaintSensorEvent p = (RsPaintSensorEvent) e;
                return new RsPaintSensorEvent(t, p.sensorID, p.x, p.y, p.status, p.region);
            }
            case RsEvent.EVT_HEARTBEAT:
                return new RsHeartbeatEvent(t, ((RsHeartbeatEvent) e).sequence);
            case RsEvent.EVT_ENCODER_STATUS: {
                RsEncoderStatusEvent s = (RsEncoderStatusEvent) e;
                return new RsEncoderStatusEvent(t, s.requestIndex, s.encoderID, s.accumulatorValue,
                        s.absoluteAccumulatorValue, s.quadratureValue, s.encoderInterval, s.encoderAngle,
                        s.clearOnReport);
            }
            default:
                throw new IllegalArgumentException("unknown event code " + e.eventID + " in " + e);
        }
    }

    private static String text(String s) {
        return s == null ? "" : s;
    }

    private static int indexOf(RsEvent e) {
        return e instanceof RsSensorEvent ? ((RsSensorEvent) e).sensorID : 0;
    }

    /** Reads everything after the header of an EVENT transaction. */
    static Decoded decode(WireIn in) throws IOException {
        int code = in.i32("event code");
        if (code < 0 || code > RsEvent.EVT_MAX_CODE) {
            throw new RsProtocolException("event code", "unknown code " + code);
        }
        int index = in.i32("event index");
        double t = in.f64("event simTime");
        int interlock = in.i32("event interlock");
        return new Decoded(decodePayload(in, code, index, t), interlock);
    }

    private static RsEvent decodePayload(WireIn in, int code, int index, double t) throws IOException {
        switch (code) {
            case RsEvent.EVT_CONTACT_SENSOR: {
                boolean status = in.bool("contact sensor status");
                return new RsContactSensorEvent(t, index, status, in.str("contact sensor object name"));
            }
            case RsEvent.EVT_MOUSE_CLICK:
                return new RsMouseClickEvent(t, in.i32("mouse click button"), in.i32("mouse click count"),
                        in.f64("mouse click x"), in.f64("mouse click y"));
            case RsEvent.EVT_POSITION:
                return new RsPositionEvent(t, in.f64("position x"), in.f64("position y"),
                        in.f64("position orientation"), in.f64("position velocity"), in.f64("position turn rate"));
            case RsEvent.EVT_RANGE_SENSOR:
                return decodeRange(in, t, index);
            case RsEvent.EVT_TARGET_SENSOR:
                return decodeTarget(in, t, index);
            case RsEvent.EVT_TIMEOUT:
                return new RsTimeoutEvent(t, in.i32("timeout index"));
            case RsEvent.EVT_MOTION_STARTED:
                return new RsMotionStartedEvent(t, in.f64("motion started linear velocity"),
                        in.f64("motion started rotational velocity"), in.f64("motion started duration"),
                        in.f64("motion started x"), in.f64("motion started y"), in.f64("motion started orientation"));
            case RsEvent.EVT_MOTION_HALTED:
                return new RsMotionHaltedEvent(t, in.i32("motion halted cause"), in.f64("motion halted x"),
                        in.f64("motion halted y"), in.f64("motion halted orientation"), in.f64("motion halted duration"));
            case RsEvent.EVT_PLACEMENT: {
                boolean valid = in.bool("placement valid");
                return new RsPlacementEvent(t, valid, in.str("placement name"), in.f64("placement x"),
                        in.f64("placement y"), in.f64("placement orientation"));
            }
            case RsEvent.EVT_TARGET_SELECTION: {
                boolean status = in.bool("target selection status");
                return new RsTargetSelectionEvent(t, in.str("target selection name"), status);
            }
            case RsEvent.EVT_PLAN:
                return new RsPlanEvent(t, PlanCodec.decode(in));
            case RsEvent.EVT_PAINT_SENSOR:
                return new RsPaintSensorEvent(t, index, in.f64("paint sensor x"), in.f64("paint sensor y"),
                        in.bool("paint sensor status"), in.i32("paint sensor region"));
            case RsEvent.EVT_HEARTBEAT:
                return new RsHeartbeatEvent(t, in.i32("heartbeat sequence"));
            default:
                return new RsEncoderStatusEvent(t, in.i32("encoder request index"), in.i32("encoder id"),
                        in.i32("encoder accumulator"), in.i32("encoder absolute accumulator"),
                        in.i32("encoder quadrature"), in.i32("encoder interval"), in.f64("encoder angle"),
                        in.bool("encoder clear on report"));
        }
    }

    private static RsEvent decodeRange(WireIn in, double t, int index) throws IOException {
        double x = in.f64("range sensor x");
        double y = in.f64("range sensor y");
        boolean status = in.bool("range sensor status");
        double ux = in.f64("range sensor ux");
        double uy = in.f64("range sensor uy");
        double range = in.f64("range sensor range");
        return new RsRangeSensorEvent(t, index, x, y, ux, uy, status, range, in.str("range sensor object name"));
    }

    private static RsEvent decodeTarget(WireIn in, double t, int index) throws IOException {
        double x = in.f64("target sensor x");
        double y = in.f64("target sensor y");
        boolean status = in.bool("target sensor status");
        double ux = in.f64("target sensor ux");
        double uy = in.f64("target sensor uy");
        double xd = in.f64("target sensor xDetection");
        double yd = in.f64("target sensor yDetection");
        double range = in.f64("target sensor range");
        double bearing = in.f64("target sensor bearing");
        return new RsTargetSensorEvent(t, index, x, y, ux, uy, status, xd, yd, range, bearing,
                in.str("target sensor target name"));
    }
}
