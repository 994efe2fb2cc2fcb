package rp1.rossum;

import java.awt.Graphics;

/**
 * A physical part of the robot with a polygonal outline (chassis, housing, bumper): drawn, and it
 * collides with walls. The outline is given in body coordinates (x forward, y left, metres) and is
 * closed automatically; edges shorter than 1 mm are dropped (protocol.md section 8.3). Sensors,
 * painters, circles and wheels are shapes too.
 */
public class RsBodyShape extends RsBodyPart {
    private static final long serialVersionUID = 1L;
    /** Distance from a wall (metres) below which a placement is not clear. */
    private static final double CLEARANCE = 1.0e-4;

    /** The closed outline as edges, body coordinates. */
    private RsSegment[] outline;

    /** A shape with no outline (it neither collides nor draws). */
    public RsBodyShape() {
        outline = new RsSegment[0];
    }

    /**
     * A shape through the first {@code nPoint} points of {@code point} (x0, y0, x1, y1, ...).
     *
     * @throws IllegalArgumentException if nPoint is negative or the array is too short
     */
    public RsBodyShape(double[] point, int nPoint) {
        setOutline(point, nPoint);
    }

    /** Replaces the outline (used by subclasses that derive it from other parameters). */
    final void setOutline(double[] point, int nPoint) {
        outline = BodyOutline.edgesFromPoints(point, nPoint);
        refBounds = BodyOutline.bounds(outline);
    }

    /** Copies of the outline's edges in body coordinates, in order. */
    public RsSegment[] getSegmentArray() {
        return BodyOutline.copy(outline);
    }

    /**
     * The outline's vertices x0, y0, x1, y1, ... (the start point of every edge, first vertex not
     * repeated): what a body specification transmits, and enough to rebuild the same outline.
     */
    public double[] getOutlineVertices() {
        return PlanPolygons.openVertices(outline);
    }

    /** The number of edges (equal to the number of transmitted vertices). */
    public int getOutlineEdgeCount() {
        return outline.length;
    }

    /** The outline used for drawing; shared, not copied. */
    RsSegment[] outline() {
        return outline;
    }

    @Override
    RsSegment[] collisionOutline() {
        return outline;
    }

    /** Fills the outline, then draws it, in the current (hot or cold) colours; null colours are skipped. */
    @Override
    public void paint(Graphics g, RsTransform t) {
        PlanPolygons.paint(g, t, outline, getFillColor(), getLineColor());
    }

    /**
     * The placement clear test for this shape at {@code pose} (behavior.md section 7): true if any edge
     * crosses a wall edge, any vertex is inside or within 1e-4 m of a wall polygon, or any wall vertex
     * is inside or within 1e-4 m of this outline. A shape without an outline never overlaps.
     */
    public boolean checkForOverlap(RsPlan plan, RsTransform pose) {
        return plan != null && checkForOverlap(plan.getWallArray(), pose);
    }

    /** As {@link #checkForOverlap(RsPlan, RsTransform)}, against the given obstacles. */
    public boolean checkForOverlap(RsWall[] walls, RsTransform pose) {
        if (outline.length == 0 || walls == null) {
            return false;
        }
        RsSegment[] body = BodyOutline.map(outline, pose);
        RsRectangle box = BodyOutline.bounds(body);
        for (RsWall wall : walls) {
            if (wall.getPolygon() != null && !farApart(box, BodyOutline.bounds(wall.getSegmentArray()))
                    && overlaps(body, wall)) {
                return true;
            }
        }
        return false;
    }

    /**
     * Whether the boxes of the body and a wall (each around its edges' starts, all the vertices of a
     * closed outline) keep more than twice the clearance apart: then no edge of either crosses one of
     * the other and no vertex of either comes within the clearance of the other (rounding moves these
     * coordinates by far less), so {@link #overlaps} would say no. Most walls a placement is tested
     * against are far from the body, and testing each in full (every edge against every edge, every
     * vertex against every edge) was 7.7 % of a sweep of short runs.
     */
    private static boolean farApart(RsRectangle a, RsRectangle b) {
        double far = 2 * CLEARANCE;
        return b.x > a.x + a.width + far || a.x > b.x + b.width + far
                || b.y > a.y + a.height + far || a.y > b.y + b.height + far;
    }

    private static boolean overlaps(RsSegment[] body, RsWall wall) {
        RsSegment[] edges = wall.getSegmentArray();
        RsSegSect sect = new RsSegSect();
        for (RsSegment b : body) {
            for (RsSegment w : edges) {
                if (sect.process(b, w)) {
                    return true;
                }
            }
            if (wall.getPolygon().checkContainment(b.x, b.y, CLEARANCE) != RsPolygon.OUTSIDE) {
                return true;
            }
        }
        for (RsSegment w : edges) {
            if (BodyOutline.insideOrNear(body, w.x, w.y, CLEARANCE)) {
                return true;
            }
        }
        return false;
    }
}
