package rp1.rossum;

import static rp1.rossum.wire.WireCodes.ACKERMAN;
import static rp1.rossum.wire.WireCodes.CASTER;
import static rp1.rossum.wire.WireCodes.DIFFERENTIAL;
import static rp1.rossum.wire.WireCodes.EMPTY_SLOT;
import static rp1.rossum.wire.WireCodes.PLAIN_WHEEL;

import java.awt.Color;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;

import rp1.rossum.wire.WireIn;
import rp1.rossum.wire.WireLimits;
import rp1.rossum.wire.WireOut;

/**
 * The payload of a BODY_SPECIFICATION message (protocol.md section 8): the body's name and its parts,
 * each as id, type, type-specific geometry and parameters, name and four colours. Socket-free: it
 * works on {@link WireOut}/{@link WireIn} or byte arrays.
 *
 * <p>Deliberate differences from RP1 0.60: parts that cannot be described on the wire
 * ({@link RsBodyArt}, a bare {@link RsActuator}) are left out of the message instead of being sent as
 * "undefined" records, which made the original simulator exit; a body with nothing to send is refused
 * before any byte is written. Encoding numbers the body's parts if they have no ids yet
 * ({@link PartNumbering}); decoding gives every part the id the sender used, and the wheels of a
 * wheel system the ids following the system's.
 */
final class BodyCodec {
    private BodyCodec() {
    }

    /**
     * The payload bytes (everything after the 20-byte header) of a body specification.
     *
     * @throws IllegalArgumentException if the body has no part that can be transmitted, or a name is
     *         too long for the wire
     */
    static byte[] encode(RsBody body) {
        WireOut out = new WireOut();
        encode(out, body);
        return out.toByteArray();
    }

    /**
     * Decodes a payload produced by {@link #encode(RsBody)} (or by an RP1 0.60 client).
     *
     * @throws RsProtocolException naming the field if the bytes are malformed or truncated, or a
     *         number is NaN or infinite
     */
    static RsBody decode(byte[] payload) throws IOException {
        return decode(WireIn.of(payload));
    }

    /**
     * The body the payload describes, as the server decodes it; refuses a payload that the server
     * would refuse: one whose dimensions include NaN or an infinity (decoding checks every number).
     *
     * @throws IllegalArgumentException naming the first such field
     */
    static RsBody checked(WireOut payload) {
        try {
            return decode(payload.toByteArray());
        } catch (RsProtocolException e) {
            throw new IllegalArgumentException("body " + e.getMessage(), e);
        } catch (IOException e) {
            throw new IllegalStateException("a body this library encoded cannot be decoded", e);
        }
    }

    /** Writes the payload of a body specification; see {@link #encode(RsBody)}. */
    static void encode(WireOut out, RsBody body) {
        PartNumbering.number(body);
        List<RsBodyPart> parts = new ArrayList<>();
        for (RsBodyPart p : body.getBodyPartArray()) {
            if (partType(p) != RsProtocol.UNDEFINED_BODY_PART) {
                parts.add(p);
            }
        }
        if (parts.isEmpty()) {
            throw new IllegalArgumentException("body \"" + body.getName()
                    + "\" has no part that can be sent to the simulator (body art and bare actuators cannot)");
        }
        out.str(body.getName());
        out.i32(parts.size());
        for (RsBodyPart p : parts) {
            writePart(out, p);
        }
    }

    /** The wire type of a part, in RP1 0.60's order of tests (circle before shape, and so on). */
    static int partType(RsBodyPart p) {
        if (p instanceof RsBodyCircle) {
            return RsProtocol.BODY_CIRCLE;
        } else if (p instanceof RsBodyTargetSensor) {
            return RsProtocol.BODY_TARGET_SENSOR;
        } else if (p instanceof RsBodyContactSensor) {
            return RsProtocol.BODY_CONTACT_SENSOR;
        } else if (p instanceof RsBodyRangeSensor) {
            return RsProtocol.BODY_RANGE_SENSOR;
        } else if (p instanceof RsBodyPaintSensor) {
            return RsProtocol.BODY_PAINT_SENSOR;
        } else if (p instanceof RsBodyPainter) {
            return RsProtocol.BODY_PAINTER;
        } else if (p instanceof RsWheelSystem) {
            return RsProtocol.WHEEL_SYSTEM;
        } else if (p instanceof RsBodyShape) {
            return RsProtocol.BODY_SHAPE;
        }
        return RsProtocol.UNDEFINED_BODY_PART;
    }

    private static void writePart(WireOut out, RsBodyPart p) {
        int type = partType(p);
        out.i32(p.getID()).i32(type);
        switch (type) {
            case RsProtocol.BODY_CIRCLE:
                RsBodyCircle c = (RsBodyCircle) p;
                out.f64(c.refXCenter).f64(c.refYCenter).f64(c.refRadius);
                break;
            case RsProtocol.BODY_TARGET_SENSOR:
                writeTargetSensor(out, (RsBodyTargetSensor) p);
                break;
            case RsProtocol.BODY_RANGE_SENSOR:
                RsBodyRangeSensor r = (RsBodyRangeSensor) p;
                writeOutline(out, r);
                out.f64(r.xDetector).f64(r.yDetector).f64(r.sightAngle).f64(r.maxRange).i32(r.nRangeBin);
                break;
            case RsProtocol.BODY_PAINT_SENSOR:
                writePaintSensor(out, (RsBodyPaintSensor) p);
                break;
            case RsProtocol.WHEEL_SYSTEM:
                writeWheelSystem(out, (RsWheelSystem) p);
                break;
            default:
                writeOutline(out, (RsBodyShape) p);
                break;
        }
        out.str(p.getName())
                .color(p.getColdFillColor())
                .color(p.getColdLineColor())
                .color(p.getHotFillColor())
                .color(p.getHotLineColor());
    }

    /** SEGLIST: the number of edges, then the start point of every edge. */
    private static void writeOutline(WireOut out, RsBodyShape s) {
        double[] xy = s.getOutlineVertices();
        out.i32(xy.length / 2);
        for (double v : xy) {
            out.f64(v);
        }
    }

    private static void writeTargetSensor(WireOut out, RsBodyTargetSensor t) {
        writeOutline(out, t);
        out.f64(t.xDetector).f64(t.yDetector).f64(t.sightAngle).f64(t.width).f64(t.maxRange)
                .i32(t.nWidthBin).i32(t.nRangeBin);
    }

    private static void writePaintSensor(WireOut out, RsBodyPaintSensor s) {
        writeOutline(out, s);
        out.f64(s.xDetector).f64(s.yDetector);
        int[] regions = s.regionSensitivity;
        out.i32(regions == null ? 0 : regions.length);
        if (regions != null) {
            for (int r : regions) {
                out.i32(r);
            }
        }
    }

    private static void writeWheelSystem(WireOut out, RsWheelSystem w) {
        if (w instanceof RsAckermanSteering) {
            RsAckermanSteering a = (RsAckermanSteering) w;
            out.i32(ACKERMAN).f64(a.trackWidth).f64(a.wheelBase).f64(a.driveWheelRadius)
                    .f64(Double.isNaN(a.decodedFrom) ? a.maxAbsSteeringAngle : a.decodedFrom).bool(a.dualSteering);
        } else {
            out.i32(DIFFERENTIAL).f64(w.trackWidth).f64(w.driveWheelRadius);
        }
        out.i32(w.wheels.length);
        for (RsWheel wheel : w.wheels) {
            out.i32(wheel instanceof RsWheelCaster ? CASTER : PLAIN_WHEEL);
            writeOutline(out, wheel);
            out.f64(wheel.getX()).f64(wheel.getY()).f64(wheel.getWheelRadius())
                    .f64(wheel.getMaxAbsSteeringAngle()).i32(wheel.encoderIntervalCount);
        }
    }

    /** Reads the payload of a body specification; see {@link #decode(byte[])}. */
    static RsBody decode(WireIn in) throws IOException {
        RsBody body = new RsBody(in.str("bodyName"));
        int n = in.count("nParts", WireLimits.MAX_BODY_PARTS);
        for (int k = 0; k < n; k++) {
            String field = "part[" + k + "]";
            int id = in.i32(field + ".partID");
            if (id == EMPTY_SLOT) {
                continue;
            }
            int type = in.i32(field + ".partType");
            if (type == RsProtocol.UNDEFINED_BODY_PART) {
                continue;
            }
            body.addPart(readPartWithId(in, field, id, type));
        }
        if (body.getBodyPartArray().length == 0) {
            // A client library cannot send such a body (section 16 of protocol.md); the original server
            // exited on the undefined parts. A robot of no parts has nothing to move, touch or record.
            throw new RsProtocolException("nParts", n == 0 ? "a body needs at least one part"
                    : "a body needs at least one part of a defined type (all " + n + " are undefined or empty)");
        }
        return body;
    }

    /** Builds the part with the transmitted id, and the wheels of a wheel system with the ids following it. */
    private static RsBodyPart readPartWithId(WireIn in, String field, int id, int type) throws IOException {
        RsBodyPart part = readPart(in, field, type);
        part.assignID(id);
        if (part instanceof RsWheelSystem) {
            RsWheel[] wheels = ((RsWheelSystem) part).wheels;
            for (int k = 0; k < wheels.length; k++) {
                wheels[k].assignID(id + 1 + k);
            }
        }
        readNameAndColors(in, field, part);
        return part;
    }

    private static RsBodyPart readPart(WireIn in, String f, int type) throws IOException {
        switch (type) {
            case RsProtocol.WHEEL_SYSTEM:
                return readWheelSystem(in, f);
            case RsProtocol.BODY_CIRCLE:
                return new RsBodyCircle(in.finite(f + ".xCenter"), in.finite(f + ".yCenter"), in.finite(f + ".radius"));
            case RsProtocol.BODY_SHAPE:
                return readShape(in, f, RsBodyShape::new);
            case RsProtocol.BODY_TARGET_SENSOR:
                return readTargetSensor(in, f);
            case RsProtocol.BODY_CONTACT_SENSOR:
                return readShape(in, f, RsBodyContactSensor::new);
            case RsProtocol.BODY_RANGE_SENSOR:
                return readRangeSensor(in, f);
            case RsProtocol.BODY_PAINT_SENSOR:
                return readPaintSensor(in, f);
            case RsProtocol.BODY_PAINTER:
                return readShape(in, f, RsBodyPainter::new);
            case RsProtocol.BODY_SENSOR:
                throw new RsProtocolException(f + ".partType", "type 4 (abstract BODY_SENSOR) cannot be built");
            default:
                throw new RsProtocolException(f + ".partType", "unknown body part type " + type);
        }
    }

    /** Builds a shape-like part from its outline. */
    private interface OutlinePart {
        RsBodyPart build(double[] points, int nPoints);
    }

    private static RsBodyPart readShape(WireIn in, String f, OutlinePart kind) throws IOException {
        double[] p = readOutline(in, f + ".outline");
        return kind.build(p, p.length / 2);
    }

    /** SEGLIST: the vertex count, then x, y of each vertex. */
    private static double[] readOutline(WireIn in, String f) throws IOException {
        int n = in.count(f + " count", WireLimits.MAX_OUTLINE_VERTICES);
        double[] p = new double[2 * n];
        for (int i = 0; i < n; i++) {
            p[2 * i] = in.finite(f + "[" + i + "].x");
            p[2 * i + 1] = in.finite(f + "[" + i + "].y");
        }
        return p;
    }

    private static RsBodyPart readTargetSensor(WireIn in, String f) throws IOException {
        double[] p = readOutline(in, f + ".outline");
        return new RsBodyTargetSensor(p, p.length / 2, in.finite(f + ".xDetector"), in.finite(f + ".yDetector"),
                in.finite(f + ".sightAngle"), in.finite(f + ".width"), in.finite(f + ".maxRange"),
                in.i32(f + ".nWidthBin"), in.i32(f + ".nRangeBin"));
    }

    private static RsBodyPart readRangeSensor(WireIn in, String f) throws IOException {
        double[] p = readOutline(in, f + ".outline");
        return new RsBodyRangeSensor(p, p.length / 2, in.finite(f + ".xDetector"), in.finite(f + ".yDetector"),
                in.finite(f + ".sightAngle"), in.finite(f + ".maxRange"), in.i32(f + ".nRangeBin"));
    }

    private static RsBodyPart readPaintSensor(WireIn in, String f) throws IOException {
        double[] p = readOutline(in, f + ".outline");
        RsBodyPaintSensor s = new RsBodyPaintSensor(p, p.length / 2,
                in.finite(f + ".xDetector"), in.finite(f + ".yDetector"));
        int n = in.count(f + ".nRegions", WireLimits.MAX_REGIONS);
        int[] regions = new int[n];
        for (int i = 0; i < n; i++) {
            regions[i] = in.i32(f + ".region[" + i + "]");
        }
        s.setRegionSensitivity(regions);
        return s;
    }

    /**
     * A wheel system and its wheels. The Ackerman steering limit on the wire is the sender's derived
     * central limit; passing it to the constructor as the inner-wheel limit derives a smaller one, as
     * RP1 0.60's simulator does.
     */
    private static RsBodyPart readWheelSystem(WireIn in, String f) throws IOException {
        RsWheelSystem system;
        if (in.i32(f + ".systemType") == DIFFERENTIAL) {
            system = new RsDifferentialSteering(in.finite(f + ".trackWidth"), in.finite(f + ".driveWheelRadius"));
        } else {
            double trackWidth = in.finite(f + ".trackWidth");
            double wheelBase = in.finite(f + ".wheelBase");
            double driveWheelRadius = in.finite(f + ".driveWheelRadius");
            double limit = in.finite(f + ".maxAbsSteeringAngle");
            RsAckermanSteering ackerman = new RsAckermanSteering(trackWidth, wheelBase, driveWheelRadius, limit,
                    in.bool(f + ".dualSteering"));
            ackerman.decodedFrom = limit;
            system = ackerman;
        }
        int n = in.count(f + ".nWheels", WireLimits.MAX_WHEELS);
        for (int k = 0; k < n; k++) {
            system.addWheel(readWheel(in, f + ".wheel[" + k + "]"));
        }
        return system;
    }

    private static RsWheel readWheel(WireIn in, String f) throws IOException {
        int wheelType = in.i32(f + ".wheelType");
        double[] p = readOutline(in, f + ".outline");
        double x = in.finite(f + ".x");
        double y = in.finite(f + ".y");
        double radius = in.finite(f + ".wheelRadius");
        double maxSteering = in.finite(f + ".maxAbsSteeringAngle");
        int intervals = in.i32(f + ".encoderIntervalCount");
        RsWheel wheel = wheelType == CASTER
                ? new RsWheelCaster(p, p.length / 2, x, y)
                : new RsWheel(p, p.length / 2, x, y, radius, maxSteering);
        wheel.addEncoder(intervals);
        return wheel;
    }

    /**
     * Name and colours. Wheels are sent without them: like RP1 0.60 they take the system's fill colour
     * as both fill and line colour (the line colour being the fill colour is the original's defect).
     */
    private static void readNameAndColors(WireIn in, String f, RsBodyPart part) throws IOException {
        part.setName(in.str(f + ".name"));
        Color fill = in.color(f + ".fillColor");
        part.setFillColor(fill);
        part.setLineColor(in.color(f + ".lineColor"));
        part.setHotFillColor(in.color(f + ".hotFillColor"));
        part.setHotLineColor(in.color(f + ".hotLineColor"));
        if (part instanceof RsWheelSystem) {
            for (RsWheel w : ((RsWheelSystem) part).wheels) {
                w.setFillColor(fill);
                w.setLineColor(fill);
            }
        }
    }
}
