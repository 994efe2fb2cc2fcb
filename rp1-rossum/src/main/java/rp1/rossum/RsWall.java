package rp1.rossum;

import java.awt.Color;
import java.awt.Graphics;

/**
 * A wall or an obstacle: a polygon the robot collides with, that blocks range sensors and hides
 * targets. A {@code wall} declaration gives a centre line and a thickness
 * ({@code x0, y0, x1, y1, thickness}) and becomes the rectangle around it; an {@code obstacle} gives
 * the polygon itself. Either way the plan event transmits the polygon's vertices.
 */
public class RsWall extends RsObject {
    /** Start of the centre line, metres (from a {@code wall} declaration, else 0). */
    protected double x0;
    /** Start of the centre line, metres (from a {@code wall} declaration, else 0). */
    protected double y0;
    /** End of the centre line, metres (from a {@code wall} declaration, else 0). */
    protected double x1;
    /** End of the centre line, metres (from a {@code wall} declaration, else 0). */
    protected double y1;
    /** Thickness, metres (from a {@code wall} declaration, else 0). */
    protected double thickness;
    /** The polygon's edges. */
    protected RsSegment[] segmentArray;
    /** The polygon robots and sensors meet. */
    protected RsPolygon polygon;

    /**
     * A wall (or obstacle) called {@code name} of {@code plan}, without geometry yet.
     *
     * @param name the wall's name, or null to have the plan name it
     * @param plan the plan it belongs to
     */
    public RsWall(String name, RsPlan plan) {
        super(name, plan);
        fillColor = Color.lightGray;
        lineColor = Color.darkGray;
    }

    /**
     * Five values ({@code x0, y0, x1, y1, thickness}) give a thick wall along the centre line; any even
     * number of six or more gives the polygon's vertices directly (obstacles, and walls received in a
     * plan event). A centre line shorter than 1e-9 m or a thickness of at most 1e-9 m leaves the
     * geometry unset.
     */
    @Override
    public void setGeometry(double[] g) {
        if (g != null && g.length == 5) {
            setCentreLine(g[0], g[1], g[2], g[3], g[4]);
        } else {
            setVertices(g);
        }
    }

    private void setVertices(double[] xy) {
        polygon = PlanPolygons.toPolygon(xy);
        segmentArray = polygon == null ? null : polygon.segment;
        isGeometrySet = polygon != null;
    }

    private void setCentreLine(double ax, double ay, double bx, double by, double w) {
        double dx = bx - ax;
        double dy = by - ay;
        double len = Math.sqrt(dx * dx + dy * dy);
        if (len <= 1.0e-9 || w <= 1.0e-9) {
            setVertices(null);
            return;
        }
        x0 = ax;
        y0 = ay;
        x1 = bx;
        y1 = by;
        thickness = w;
        double nx = -dy * (w / 2.0 / len);
        double ny = dx * (w / 2.0 / len);
        setVertices(new double[] {
            ax - nx, ay - ny,
            bx - nx, by - ny,
            bx + nx, by + ny,
            ax + nx, ay + ny});
    }

    /** The polygon's vertices x0, y0, x1, y1, ... (first vertex not repeated), as transmitted. */
    @Override
    public double[] getGeometry() {
        return PlanPolygons.openVertices(segmentArray);
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

    /** The thickness given in a wall declaration (0 for obstacles and received walls). */
    public double getThickness() {
        return thickness;
    }

    @Override
    public String getClassName() {
        return "wall";
    }
}
