package rp1.web;

import java.util.List;
import java.util.Objects;

import rp1.rossum.RsBodyCircle;
import rp1.rossum.RsBodyPart;
import rp1.rossum.RsBodyRangeSensor;
import rp1.rossum.RsBodyShape;
import rp1.rossum.RsBodyTargetSensor;
import rp1.rossum.RsWheel;
import rp1.simulator.snapshot.PartSnapshot;
import rp1.simulator.snapshot.RobotSnapshot;

/**
 * One robot in the page's encoding: its body once (parts' geometry and colours never change), then
 * its pose each frame it changed (frame, x, y and heading each as the difference from the one
 * before) and change lists of being on the floor and of its parts' state (hot, steering, range
 * reading, target seen).
 */
final class RobotTrack {
    private final int number;
    private String body;
    private final StringBuilder poses = new StringBuilder();
    private final StringBuilder placed = new StringBuilder();
    private final StringBuilder hot = new StringBuilder();
    private final StringBuilder steering = new StringBuilder();
    private final StringBuilder ranges = new StringBuilder();
    private Json seen = new Json().beginArray();
    private boolean anySeen;
    private int lastFrame;
    /** Whether a pose has been written yet (the first one is written even if it is the origin). */
    private boolean posed;
    private long x;
    private long y;
    private long theta;
    private boolean onFloor;
    private final boolean[] partHot;
    private final long[] partSteering;
    private final long[] partRange;
    private final String[] partSeen;

    RobotTrack(RobotSnapshot r) {
        number = r.number();
        body = body(r);
        int n = r.parts().size();
        partHot = new boolean[n];
        partSteering = new long[n];
        partRange = new long[n];
        partSeen = new String[n];
    }

    void frame(int f, RobotSnapshot r, Object[] readings) {
        if (r.placed() != onFloor) {
            onFloor = r.placed();
            Encoding.append(placed, f, onFloor ? 1 : 0);
        }
        long nx = Encoding.metres(r.x());
        long ny = Encoding.metres(r.y());
        long nt = Encoding.radians(r.theta());
        if (r.placed() && (nx != x || ny != y || nt != theta || !posed)) {
            posed = true;
            Encoding.append(poses, f - lastFrame, nx - x, ny - y, nt - theta);
            lastFrame = f;
            x = nx;
            y = ny;
            theta = nt;
        }
        List<PartSnapshot> parts = r.parts();
        for (int i = 0; i < parts.size() && i < partHot.length; i++) {
            parts(f, i, parts.get(i), readings[i]);
        }
    }

    private void parts(int f, int i, PartSnapshot p, Object reading) {
        if (p.hot() != partHot[i]) {
            partHot[i] = p.hot();
            Encoding.append(hot, f, i, p.hot() ? 1 : 0);
        }
        long s = Encoding.radians(p.steering());
        if (s != partSteering[i]) {
            partSteering[i] = s;
            Encoding.append(steering, f, i, s);
        }
        if (reading instanceof Double range) {
            long q = Encoding.metres(range);
            if (q != partRange[i]) {
                partRange[i] = q;
                Encoding.append(ranges, f, i, q);
            }
        } else if (p.part() instanceof RsBodyTargetSensor && !Objects.equals(reading, partSeen[i])) {
            partSeen[i] = (String) reading;
            seen.value(f).value(i).value(partSeen[i]);
            anySeen = true;
        }
    }

    /** The robot has left the world (its client departed): it is off the floor from frame {@code f}. */
    void absent(int f) {
        if (onFloor) {
            onFloor = false;
            Encoding.append(placed, f, 0);
        }
    }

    /** Writes what changed since the last take, if anything, and forgets it. */
    void take(Json j) {
        if (body == null && poses.length() == 0 && placed.length() == 0 && hot.length() == 0
                && steering.length() == 0 && ranges.length() == 0 && !anySeen) {
            return;
        }
        j.beginObject().key("n").value(number);
        if (body != null) {
            j.key("body").raw(body);
            body = null;
        }
        list(j, "p", poses);
        list(j, "pl", placed);
        list(j, "h", hot);
        list(j, "w", steering);
        list(j, "r", ranges);
        j.key("g").raw(seen.endArray().toString());
        seen = new Json().beginArray();
        anySeen = false;
        j.endObject();
    }

    private static void list(Json j, String key, StringBuilder values) {
        j.key(key).raw("[" + values + "]");
        values.setLength(0);
    }

    /** The robot's name and parts as the window's painter draws them. */
    private static String body(RobotSnapshot r) {
        Json j = new Json().beginObject().key("name").value(r.label()).key("parts").beginArray();
        for (PartSnapshot p : r.parts()) {
            RsBodyPart part = p.part();
            j.beginObject();
            if (part instanceof RsBodyCircle c) {
                j.key("k").value("circle").key("x").value(c.getXCenter()).key("y").value(c.getYCenter())
                        .key("r").value(c.getRadius());
            } else if (part instanceof RsBodyShape s) {
                j.key("k").value(part instanceof RsWheel ? "wheel" : "shape");
                j.key("xy").beginArray();
                for (double v : s.getOutlineVertices()) {
                    j.value(v);
                }
                j.endArray();
                if (part instanceof RsWheel w) {
                    j.key("hub").beginArray().value(w.getX()).value(w.getY()).endArray();
                }
            } else {
                j.key("k").value("none");
            }
            if (part instanceof RsBodyRangeSensor s) {
                j.key("ray").beginArray().value(s.getXDetector()).value(s.getYDetector()).value(s.getSightAngle())
                        .endArray();
            } else if (part instanceof RsBodyTargetSensor s) {
                j.key("eye").beginArray().value(s.getXDetector()).value(s.getYDetector()).endArray();
            }
            j.key("cf").color(part.getColdFillColor()).key("cl").color(part.getColdLineColor())
                    .key("hf").color(part.getHotFillColor()).key("hl").color(part.getHotLineColor());
            j.endObject();
        }
        return j.endArray().endObject().toString();
    }
}
