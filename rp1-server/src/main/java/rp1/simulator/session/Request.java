package rp1.simulator.session;

import java.awt.Color;

import rp1.rossum.RsBody;
import rp1.rossum.request.RsMotionRequest;
import rp1.rossum.request.RsPainterChangeRequest;
import rp1.rossum.request.RsTargetSelectionRequest;

/**
 * What a client asked for, as its session received it (from the wire or from an in-process client),
 * held until the boundary where it is applied. Immutable: arrays are copied in, so a client that
 * reuses its own objects cannot change a request after sending it.
 */
public sealed interface Request {
    /** Applies the request to {@code session} at {@code now} (the boundary's time). */
    void applyTo(ClientSession session, double now);

    /** A timeout event after {@code duration} (negative durations fire at once, stamped in the past). */
    record Timeout(double duration, int index) implements Request {
        @Override
        public void applyTo(ClientSession s, double now) {
            s.timeout(this, now);
        }
    }

    /** Wants (or no longer wants) events with {@code code} for sensor or index {@code index}. */
    record Subscription(int code, int index, boolean enable) implements Request {
        @Override
        public void applyTo(ClientSession s, double now) {
            s.subscription(this);
        }
    }

    /** The last computed state of one sensor. */
    record SensorStatus(int sensorId) implements Request {
        @Override
        public void applyTo(ClientSession s, double now) {
            s.sensorStatus(this, now);
        }
    }

    /** A motion request. */
    record Motion(RsMotionRequest motion) implements Request {
        @Override
        public void applyTo(ClientSession s, double now) {
            s.motion(motion, now);
        }
    }

    /** A command for an actuator (the wheel system): parameter values by position. */
    record ActuatorControl(int actuatorId, int commandId, String[] names, double[] values) implements Request {
        public ActuatorControl {
            names = names.clone();
            values = values.clone();
        }

        /** The parameter values, in order (a copy). */
        public double[] valuesCopy() {
            return values.clone();
        }

        /** The parameter names, in order (a copy). */
        public String[] namesCopy() {
            return names.clone();
        }

        @Override
        public void applyTo(ClientSession s, double now) {
            s.actuatorControl(this, now);
        }
    }

    /** Stop now. */
    record Halt() implements Request {
        @Override
        public void applyTo(ClientSession s, double now) {
            s.halt(now);
        }
    }

    /** Where the robot is. */
    record Position() implements Request {
        @Override
        public void applyTo(ClientSession s, double now) {
            s.position(now);
        }
    }

    /** Put the robot at a named placement ("" for a random one, "$random" for a random pose). */
    record Placement(String name) implements Request {
        public Placement {
            name = name == null ? "" : name;
        }

        @Override
        public void applyTo(ClientSession s, double now) {
            s.placement(name, now);
        }
    }

    /** Select or deselect targets. */
    record TargetSelection(boolean random, String name, boolean status, boolean exclusive) implements Request {
        public TargetSelection {
            name = name == null ? "" : name;
        }

        /** As the plan takes it. */
        RsTargetSelectionRequest toRequest() {
            return new RsTargetSelectionRequest(random, name, status, exclusive);
        }

        @Override
        public void applyTo(ClientSession s, double now) {
            s.targetSelection(this, now);
        }
    }

    /** The floor plan. */
    record Plan() implements Request {
        @Override
        public void applyTo(ClientSession s, double now) {
            s.plan(now);
        }
    }

    /** A heartbeat every {@code interval} seconds (at least {@link Heartbeats#MIN_INTERVAL}); 0 or less stops it. */
    record Heartbeat(double interval) implements Request {
        @Override
        public void applyTo(ClientSession s, double now) {
            s.heartbeat(interval, now);
        }
    }

    /** Activates, deactivates or erases a painter. */
    record PainterChange(int painterId, boolean erasure, boolean activation, boolean trailerDefined,
                         double xTrailer, double yTrailer, double wTrailer, Color[] colors) implements Request {
        public PainterChange {
            colors = colors == null ? null : colors.clone();
        }

        static PainterChange of(RsPainterChangeRequest r) {
            return new PainterChange(r.painterID, r.erasure, r.activation, r.trailerDefined, r.xTrailer,
                    r.yTrailer, r.wTrailer, r.color);
        }

        /** As the painter takes it. */
        public RsPainterChangeRequest toRequest() {
            return new RsPainterChangeRequest(painterId, erasure, activation, trailerDefined, xTrailer, yTrailer,
                    wTrailer, colors == null ? null : colors.clone());
        }

        @Override
        public void applyTo(ClientSession s, double now) {
            s.painterChange(this, now);
        }
    }

    /** The states of some encoders, one event each, in order. */
    record EncoderStatus(int requestIndex, int[] ids, boolean clear) implements Request {
        public EncoderStatus {
            ids = ids.clone();
        }

        /** The encoder ids, in order (a copy). */
        public int[] idsCopy() {
            return ids.clone();
        }

        @Override
        public void applyTo(ClientSession s, double now) {
            s.encoderStatus(this, now);
        }
    }

    /** The robot's body (the session's own decoded copy). */
    record Body(RsBody body) implements Request {
        @Override
        public void applyTo(ClientSession s, double now) {
            s.body(body);
        }
    }

    /** The client left. */
    record Departure() implements Request {
        @Override
        public void applyTo(ClientSession s, double now) {
            s.depart();
        }
    }
}
