package rp1.rossum;

import java.awt.Color;
import java.awt.Graphics;
import java.util.Arrays;

/**
 * Floor paint: a coloured polygon on the floor that paint sensors detect, carrying a region code. It
 * does not block motion or sensors. Where paint overlaps, the one declared last lies on top.
 */
public class RsPaint extends RsObject {
    /** The polygon's edges; null without geometry. */
    protected RsSegment[] segmentArray;
    /** The polygon; null without geometry. */
    protected RsPolygon polygon;
    /** The region code paint sensors report. */
    protected int region;

    /**
     * Paint called {@code name} of {@code plan}, without a polygon yet; light grey, region 0.
     *
     * @param name the paint's name, or null to have the plan name it
     * @param plan the plan it belongs to
     */
    public RsPaint(String name, RsPlan plan) {
        super(name, plan);
        fillColor = Color.lightGray;
        lineColor = Color.lightGray;
    }

    /** The polygon's vertices x0, y0, x1, y1, ... (a repeated first vertex at the end is dropped). */
    @Override
    public void setGeometry(double[] g) {
        polygon = PlanPolygons.toPolygon(g);
        segmentArray = polygon == null ? null : polygon.segment;
        isGeometrySet = polygon != null;
    }

    /** The vertices with the first one repeated at the end, as the plan event transmits paint. */
    @Override
    public double[] getGeometry() {
        double[] open = PlanPolygons.openVertices(segmentArray);
        if (open.length == 0) {
            return open;
        }
        double[] closed = Arrays.copyOf(open, open.length + 2);
        closed[open.length] = open[0];
        closed[open.length + 1] = open[1];
        return closed;
    }

    /** The region code paint sensors report (0 unless the plan gives one; never transmitted). */
    public int getRegion() {
        return region;
    }

    /**
     * Sets the region code paint sensors report over this paint.
     *
     * @param region the code
     */
    public void setRegion(int region) {
        this.region = region;
    }

    /** The polygon's edges (empty if no geometry is set). */
    public RsSegment[] getSegmentArray() {
        return segmentArray == null ? new RsSegment[0] : segmentArray;
    }

    /** The polygon, or null if no geometry is set. */
    public RsPolygon getPolygon() {
        return polygon;
    }

    @Override
    protected RsRectangle computeBounds() {
        return polygon.getBounds();
    }

    /** Fills the polygon in the fill colour and outlines it in the line colour. */
    @Override
    public void paint(Graphics g, RsTransform t) {
        PlanPolygons.paint(g, t, segmentArray, fillColor, lineColor);
    }

    @Override
    public String getClassName() {
        return "paint";
    }
}
