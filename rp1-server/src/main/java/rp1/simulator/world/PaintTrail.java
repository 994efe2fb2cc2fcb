package rp1.simulator.world;

import java.awt.Color;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

import rp1.rossum.RsBodyPainter;
import rp1.rossum.RsPoint;
import rp1.rossum.RsTransform;
import rp1.rossum.request.RsPainterChangeRequest;

/**
 * The trail one painter leaves (behavior.md section 9): while the painter is active, has a colour and
 * a positive width, its trailer point is recorded at every motion evaluation, at least 1 cm from the
 * previous point. A change of trailer, width or colours, a re-activation, or a new placement starts a
 * new, unconnected segment.
 */
public final class PaintTrail {
    /** The server never learns the client's minimum segment length; RP1 0.60 uses 1 cm. */
    static final double MIN_SPACING = 0.01;

    private final RsBodyPainter painter;
    private final List<TrailSegment> segments = new CopyOnWriteArrayList<>();
    private boolean active;
    private double trailerX;
    private double trailerY;
    private double width;
    private Color[] colors;
    private TrailSegment current;
    private int series = Integer.MIN_VALUE;

    PaintTrail(RsBodyPainter painter) {
        this.painter = painter;
    }

    public int getPainterID() {
        return painter.getID();
    }

    /** The segments painted so far, oldest first. */
    public List<TrailSegment> getSegments() {
        return segments;
    }

    /** Applies an activation or deactivation; the painter part is drawn hot while active. */
    void apply(RsPainterChangeRequest r) {
        if (r.erasure) {
            erase();
            return;
        }
        boolean reactivated = r.activation && !active;
        active = r.activation;
        painter.setHot(active);
        if (!active) {
            return;
        }
        boolean changed = r.xTrailer != trailerX || r.yTrailer != trailerY || r.wTrailer != width
                || !Arrays.equals(r.color, colors);
        trailerX = r.xTrailer;
        trailerY = r.yTrailer;
        width = Math.max(0.0, r.wTrailer);
        colors = r.color == null ? null : r.color.clone();
        if (reactivated || changed) {
            current = null;
        }
    }

    /** Forgets everything painted; the painter's settings stay, so an active painter goes on painting. */
    void erase() {
        segments.clear();
        current = null;
    }

    /**
     * Records the trailer point at {@code pose} if the painter can paint. {@code continuitySeries}
     * identifies the robot's unbroken motion history; a new placement changes it.
     */
    void record(RsTransform pose, int continuitySeries) {
        if (!active || colors == null || colors.length == 0 || colors[0] == null || !(width > 0.0)) {
            return;
        }
        if (continuitySeries != series) {
            series = continuitySeries;
            current = null;
        }
        if (current == null || current.isFull()) {
            TrailSegment next = new TrailSegment(colors[0], width);
            if (current != null) {
                int last = current.getCount() - 1;
                next.append(current.getX(last), current.getY(last), 0.0);
            }
            current = next;
            segments.add(next);
        }
        RsPoint p = pose.map(trailerX, trailerY);
        current.append(p.x, p.y, MIN_SPACING);
    }
}
