package rp1.rossum.wire;

import java.awt.Color;
import java.io.IOException;
import java.util.function.Supplier;

import rp1.rossum.RsBody;
import rp1.rossum.RsProtocolException;
import rp1.rossum.request.RsActuatorControlRequest;
import rp1.rossum.request.RsEncoderStatusRequest;
import rp1.rossum.request.RsHaltRequest;
import rp1.rossum.request.RsHeartbeatRequest;
import rp1.rossum.request.RsMotionRequest;
import rp1.rossum.request.RsPainterChangeRequest;
import rp1.rossum.request.RsPlacementRequest;
import rp1.rossum.request.RsPlanRequest;
import rp1.rossum.request.RsRequest;
import rp1.rossum.request.RsSensorRequest;
import rp1.rossum.request.RsSubscriptionRequest;
import rp1.rossum.request.RsTargetSelectionRequest;

/**
 * Encodes and decodes the body of a REQUEST transaction (protocol.md section 6): request code,
 * request index (always written as 0), then the request's payload. Encoders return a complete
 * payload in memory; the decoder hands each request to a {@link RequestListener}, and
 * {@link #copying(RequestListener)} hands on what the decoder would give without encoding anything.
 */
public final class RequestCodec {
    private RequestCodec() {
    }

    private static WireOut prefix(int requestCode) {
        return new WireOut().i32(requestCode).i32(0);
    }

    /** The payload of a timeout request (what follows the REQUEST header). */
    public static WireOut timeout(double duration, int timeoutIndex) {
        return prefix(RsRequest.REQ_TIMEOUT).f64(duration).i32(timeoutIndex);
    }

    /** The payload of a subscription request (what follows the REQUEST header). */
    public static WireOut subscription(int eventCode, int eventIndex, boolean enable) {
        return prefix(RsRequest.REQ_SUBSCRIPTION).i32(eventCode).i32(eventIndex).bool(enable);
    }

    /** The payload of a sensor-status request (what follows the REQUEST header). */
    public static WireOut sensorStatus(int sensorID) {
        return prefix(RsRequest.REQ_SENSOR_STATUS).i32(sensorID);
    }

    /** The payload of a motion request (what follows the REQUEST header). */
    public static WireOut motion(RsMotionRequest r) {
        return prefix(RsRequest.REQ_MOTION).f64(r.linearVelocity).f64(r.rotationalVelocity).f64(r.duration);
    }

    /** The payload of a halt request (what follows the REQUEST header). */
    public static WireOut halt() {
        return prefix(RsRequest.REQ_HALT);
    }

    /** The payload of a position request (what follows the REQUEST header). */
    public static WireOut position() {
        return prefix(RsRequest.REQ_POSITION);
    }

    /**
     * A placement carries the name twice over: an i32 with the name's length in UTF-16 units (only
     * zero or non-zero matters) and, if that is non-zero, the name as a STR.
     */
    public static WireOut placement(String name) {
        WireOut out = prefix(RsRequest.REQ_PLACEMENT);
        int flag = name == null ? 0 : name.length();
        out.i32(flag);
        if (flag != 0) {
            out.str(name);
        }
        return out;
    }

    /** The payload of a target-selection request (what follows the REQUEST header). */
    public static WireOut targetSelection(boolean random, String name, boolean status, boolean exclusive) {
        return prefix(RsRequest.REQ_TARGET_SELECTION).bool(random).str(name).bool(status).bool(exclusive);
    }

    /** The payload of a plan request (what follows the REQUEST header). */
    public static WireOut plan() {
        return prefix(RsRequest.REQ_PLAN);
    }

    /** The payload of a heartbeat request (what follows the REQUEST header). */
    public static WireOut heartbeat(double interval) {
        return prefix(RsRequest.REQ_HEARTBEAT).f64(interval);
    }

    /** The payload of a painter change that erases the painter's trail (what follows the REQUEST header). */
    public static WireOut painterErasure(int painterID) {
        return prefix(RsRequest.REQ_PAINTER_CHANGE).i32(painterID).bool(true);
    }

    /** The payload of a painter change that deactivates the painter (what follows the REQUEST header). */
    public static WireOut painterDeactivation(int painterID) {
        return prefix(RsRequest.REQ_PAINTER_CHANGE).i32(painterID).bool(false).bool(false);
    }

    /** The payload of a painter change that activates the painter with a trailer of this size and these colours (what follows the REQUEST header). */
    public static WireOut painterActivation(int painterID, double x, double y, double width, Color[] colors) {
        return prefix(RsRequest.REQ_PAINTER_CHANGE).i32(painterID).bool(false).bool(true).bool(true)
                .f64(x).f64(y).f64(width).colorArray(colors);
    }

    /** The payload of an actuator command (what follows the REQUEST header). */
    public static WireOut actuatorControl(RsActuatorControlRequest r) {
        WireOut out = prefix(RsRequest.REQ_ACTUATOR_CONTROL).i32(r.actuatorID).i32(r.commandID);
        String[] names = r.getParameterNames();
        double[] values = r.getParameterValues();
        out.i32(names.length);
        for (int i = 0; i < names.length; i++) {
            out.str(names[i]).f64(values[i]);
        }
        return out;
    }

    /** The payload of an encoder-status request (what follows the REQUEST header). */
    public static WireOut encoderStatus(int requestIndex, int[] encoderIDs, boolean clearOnReport) {
        WireOut out = prefix(RsRequest.REQ_ENCODER_STATUS).i32(requestIndex).i32(encoderIDs.length);
        for (int id : encoderIDs) {
            out.i32(id);
        }
        return out.bool(clearOnReport);
    }

    /**
     * Encodes a request object whatever its type, by its request code. The client library does not use
     * it (it knows each request's type and calls the typed methods); tests use it to compare the
     * requests a server received by their encodings. Position requests have no class and are encoded
     * with {@link #position()}.
     */
    public static WireOut encode(RsRequest r) {
        switch (r.requestID) {
            case RsRequest.REQ_SUBSCRIPTION: {
                RsSubscriptionRequest s = (RsSubscriptionRequest) r;
                return subscription(s.eventCode, s.eventIndex, s.eventEnable);
            }
            case RsRequest.REQ_SENSOR_STATUS:
                return sensorStatus(((RsSensorRequest) r).sensorID);
            case RsRequest.REQ_MOTION:
                return motion((RsMotionRequest) r);
            case RsRequest.REQ_HALT:
                return halt();
            case RsRequest.REQ_PLACEMENT:
                return placement(((RsPlacementRequest) r).name);
            case RsRequest.REQ_TARGET_SELECTION: {
                RsTargetSelectionRequest t = (RsTargetSelectionRequest) r;
                return targetSelection(t.random, t.name, t.status, t.exclusive);
            }
            case RsRequest.REQ_PLAN:
                return plan();
            case RsRequest.REQ_HEARTBEAT:
                return heartbeat(((RsHeartbeatRequest) r).interval);
            case RsRequest.REQ_PAINTER_CHANGE:
                return painterChange((RsPainterChangeRequest) r);
            case RsRequest.REQ_ACTUATOR_CONTROL:
                return actuatorControl((RsActuatorControlRequest) r);
            case RsRequest.REQ_ENCODER_STATUS: {
                RsEncoderStatusRequest e = (RsEncoderStatusRequest) r;
                return encoderStatus(e.requestIndex, e.encoderID, e.clearOnReport);
            }
            default:
                throw new IllegalArgumentException("no object encoding for request " + r);
        }
    }

    /** An erasure, a deactivation or an activation, as the request says (an activation's trailer always as defined). */
    public static WireOut painterChange(RsPainterChangeRequest p) {
        if (p.erasure) {
            return painterErasure(p.painterID);
        }
        if (!p.activation) {
            return painterDeactivation(p.painterID);
        }
        return painterActivation(p.painterID, p.xTrailer, p.yTrailer, p.wTrailer, p.color);
    }

    /**
     * A sink that hands each request on to {@code target} as the object {@link #decode} would give for
     * its encoding, built without encoding it (the requests of a directly connected client, see
     * {@code RsConnection.connectDirect}): a new object of the decoded class, whatever the caller's object was, so
     * nothing the caller does with its object later reaches the server. The wire's normalisations are
     * applied: a placement name "" becomes null, a null target name or actuator parameter name "",
     * an empty colour list null, colours lose their alpha, and an activated painter's trailer counts
     * as defined. The caller's arrays are copied. A body is handed on as given: the caller passes a
     * decoded copy, which only the body codec can make.
     */
    public static RequestListener copying(RequestListener target) {
        return new Copying(() -> target);
    }

    /** As {@link #copying(RequestListener)}, to whatever listener {@code target} gives at each request. */
    public static RequestListener copying(Supplier<RequestListener> target) {
        return new Copying(target);
    }

    /**
     * Reads everything after the header of a REQUEST transaction and hands it to {@code sink}. Every
     * floating-point field must be a finite number (protocol.md section 14).
     */
    public static void decode(WireIn in, RequestListener sink) throws IOException {
        int code = in.i32("request code");
        if (code < 0 || code > RsRequest.REQ_MAX_CODE) {
            throw new RsProtocolException("request code", "unknown code " + code);
        }
        in.i32("request index");
        switch (code) {
            case RsRequest.REQ_TIMEOUT: {
                double duration = in.finite("timeout duration");
                sink.timeout(duration, in.i32("timeout index"));
                break;
            }
            case RsRequest.REQ_SUBSCRIPTION:
                sink.subscription(new RsSubscriptionRequest(in.i32("subscription event code"),
                        in.i32("subscription event index"), in.bool("subscription enable")));
                break;
            case RsRequest.REQ_SENSOR_STATUS:
                sink.sensorStatus(new RsSensorRequest(in.i32("sensor id")));
                break;
            case RsRequest.REQ_MOTION:
                sink.motion(new RsMotionRequest(in.finite("motion linear velocity"),
                        in.finite("motion rotational velocity"), in.finite("motion duration")));
                break;
            case RsRequest.REQ_HALT:
                sink.halt(new RsHaltRequest());
                break;
            case RsRequest.REQ_POSITION:
                sink.position();
                break;
            case RsRequest.REQ_SET_POSITION:
                sink.setPosition();
                break;
            case RsRequest.REQ_PLACEMENT:
                sink.placement(new RsPlacementRequest(
                        in.i32("placement name flag") == 0 ? null : in.str("placement name")));
                break;
            case RsRequest.REQ_TARGET_SELECTION: {
                boolean random = in.bool("target selection random");
                String name = in.str("target selection name");
                boolean status = in.bool("target selection status");
                sink.targetSelection(new RsTargetSelectionRequest(random, name, status,
                        in.bool("target selection exclusive")));
                break;
            }
            case RsRequest.REQ_PLAN:
                sink.plan(new RsPlanRequest());
                break;
            case RsRequest.REQ_HEARTBEAT:
                sink.heartbeat(new RsHeartbeatRequest(in.finite("heartbeat interval")));
                break;
            case RsRequest.REQ_PAINTER_CHANGE:
                sink.painterChange(decodePainterChange(in));
                break;
            case RsRequest.REQ_ACTUATOR_CONTROL:
                sink.actuatorControl(decodeActuatorControl(in));
                break;
            default:
                sink.encoderStatus(decodeEncoderStatus(in));
                break;
        }
    }

    private static RsPainterChangeRequest decodePainterChange(WireIn in) throws IOException {
        int id = in.i32("painter id");
        if (in.bool("painter erasure")) {
            return new RsPainterChangeRequest(id, true, false, false, 0.0, 0.0, 0.0, null);
        }
        if (!in.bool("painter activation")) {
            return new RsPainterChangeRequest(id, false, false, false, 0.0, 0.0, 0.0, null);
        }
        boolean defined = in.bool("painter trailer defined");
        double x = in.finite("painter trailer x");
        double y = in.finite("painter trailer y");
        double w = in.finite("painter trailer width");
        return new RsPainterChangeRequest(id, false, true, defined, x, y, w, in.colorArray("painter colors"));
    }

    private static RsActuatorControlRequest decodeActuatorControl(WireIn in) throws IOException {
        RsActuatorControlRequest r = new RsActuatorControlRequest(in.i32("actuator id"), in.i32("actuator command"));
        int n = in.count("actuator parameter count", WireLimits.MAX_ACTUATOR_PARAMETERS);
        for (int i = 0; i < n; i++) {
            String name = in.str("actuator parameter " + i + " name");
            r.addParameter(name, in.finite("actuator parameter " + i + " value"));
        }
        return r;
    }

    private static RsEncoderStatusRequest decodeEncoderStatus(WireIn in) throws IOException {
        int index = in.i32("encoder request index");
        int n = in.count("encoder id count", WireLimits.MAX_ENCODERS);
        int[] ids = new int[n];
        for (int i = 0; i < n; i++) {
            ids[i] = in.i32("encoder id " + i);
        }
        return new RsEncoderStatusRequest(index, ids, in.bool("encoder clear on report"));
    }

    /** See {@link #copying(RequestListener)}; each method mirrors the encoder and decoder of its request. */
    private static final class Copying implements RequestListener {
        private final Supplier<RequestListener> target;

        Copying(Supplier<RequestListener> target) {
            this.target = target;
        }

        @Override
        public void body(RsBody body) {
            target.get().body(body);
        }

        @Override
        public void timeout(double duration, int timeoutIndex) {
            target.get().timeout(duration, timeoutIndex);
        }

        @Override
        public void subscription(RsSubscriptionRequest r) {
            target.get().subscription(new RsSubscriptionRequest(r.eventCode, r.eventIndex, r.eventEnable));
        }

        @Override
        public void sensorStatus(RsSensorRequest r) {
            target.get().sensorStatus(new RsSensorRequest(r.sensorID));
        }

        @Override
        public void motion(RsMotionRequest r) {
            target.get().motion(new RsMotionRequest(r.linearVelocity, r.rotationalVelocity, r.duration));
        }

        @Override
        public void halt(RsHaltRequest r) {
            target.get().halt(new RsHaltRequest());
        }

        @Override
        public void position() {
            target.get().position();
        }

        @Override
        public void setPosition() {
            target.get().setPosition();
        }

        @Override
        public void placement(RsPlacementRequest r) {
            target.get().placement(new RsPlacementRequest(r.name == null || r.name.isEmpty() ? null : r.name));
        }

        @Override
        public void targetSelection(RsTargetSelectionRequest r) {
            target.get().targetSelection(new RsTargetSelectionRequest(r.random, text(r.name), r.status, r.exclusive));
        }

        @Override
        public void plan(RsPlanRequest r) {
            target.get().plan(new RsPlanRequest());
        }

        @Override
        public void heartbeat(RsHeartbeatRequest r) {
            target.get().heartbeat(new RsHeartbeatRequest(r.interval));
        }

        @Override
        public void painterChange(RsPainterChangeRequest r) {
            RsPainterChangeRequest copy;
            if (r.erasure) {
                copy = new RsPainterChangeRequest(r.painterID, true, false, false, 0.0, 0.0, 0.0, null);
            } else if (!r.activation) {
                copy = new RsPainterChangeRequest(r.painterID, false, false, false, 0.0, 0.0, 0.0, null);
            } else {
                copy = new RsPainterChangeRequest(r.painterID, false, true, true, r.xTrailer, r.yTrailer, r.wTrailer,
                        colors(r.color));
            }
            target.get().painterChange(copy);
        }

        @Override
        public void actuatorControl(RsActuatorControlRequest r) {
            RsActuatorControlRequest copy = new RsActuatorControlRequest(r.actuatorID, r.commandID);
            String[] names = r.getParameterNames();
            double[] values = r.getParameterValues();
            for (int i = 0; i < names.length; i++) {
                copy.addParameter(text(names[i]), values[i]);
            }
            target.get().actuatorControl(copy);
        }

        @Override
        public void encoderStatus(RsEncoderStatusRequest r) {
            target.get().encoderStatus(new RsEncoderStatusRequest(r.requestIndex, r.encoderID.clone(), r.clearOnReport));
        }

        /** A STR: null goes as "". */
        private static String text(String s) {
            return s == null ? "" : s;
        }

        /** A COLOR_ARRAY: null or empty arrives as null, each colour as its red, green and blue. */
        private static Color[] colors(Color[] colors) {
            if (colors == null || colors.length == 0) {
                return null;
            }
            Color[] copy = new Color[colors.length];
            for (int i = 0; i < colors.length; i++) {
                Color c = colors[i];
                copy[i] = c == null ? null : new Color(c.getRed(), c.getGreen(), c.getBlue());
            }
            return copy;
        }
    }
}
