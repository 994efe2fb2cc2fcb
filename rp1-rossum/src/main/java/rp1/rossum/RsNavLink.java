package rp1.rossum;

import java.awt.Color;
import java.awt.Graphics;

/**
 * A link ("road") of the navigation network between two {@link RsNavNode}s. Its geometry is the
 * segment between the nodes; links are drawn as thin lines and their labels are not drawn.
 */
public class RsNavLink extends RsObject {
    /** The node the link starts at ({@link #setNodes}). */
    public RsNavNode n0;
    /** The node the link ends at ({@link #setNodes}). */
    public RsNavNode n1;
    /** From {@code n0} to {@code n1}. */
    public RsSegment segment;
    /** Free for route-planning clients to mark the link. */
    public boolean visited;

    /**
     * A link called {@code name} of {@code plan}, not yet joining nodes; drawn in cyan.
     *
     * @param name the link's name, or null to have the plan name it
     * @param plan the plan it belongs to
     */
    public RsNavLink(String name, RsPlan plan) {
        super(name, plan);
        fillColor = Color.cyan;
        lineColor = Color.cyan;
    }

    /** Joins the two nodes; the geometry becomes the segment between them. */
    public void setNodes(RsNavNode n0, RsNavNode n1) {
        this.n0 = n0;
        this.n1 = n1;
        if (n0 != null && n1 != null) {
            setGeometry(new double[] {n0.x, n0.y, n1.x, n1.y});
        }
    }

    /** {@code x0, y0, x1, y1} of the segment; any other count leaves the geometry unset. */
    @Override
    public void setGeometry(double[] g) {
        if (g == null || g.length != 4) {
            isGeometrySet = false;
            return;
        }
        segment = new RsSegment(g[0], g[1], g[2], g[3]);
        isGeometrySet = true;
    }

    /** {@code x0, y0, x1, y1} (links are transmitted by node names, not geometry). */
    @Override
    public double[] getGeometry() {
        if (segment == null) {
            return new double[0];
        }
        return new double[] {segment.x, segment.y, segment.getX1(), segment.getY1()};
    }

    @Override
    public void setLabel(String label) {
        this.label = label;
    }

    /**
     * The link's label (never drawn).
     *
     * @return the label, or null
     */
    public String getLabel() {
        return label;
    }

    /** The node at the other end from {@code node}, or null if {@code node} is not an end of this link. */
    public RsNavNode getOtherNode(RsNavNode node) {
        if (node == n0) {
            return n1;
        }
        return node == n1 ? n0 : null;
    }

    /** Length of the link in metres (0 without geometry). */
    public double getLength() {
        return segment == null ? 0.0 : segment.m;
    }

    @Override
    protected RsRectangle computeBounds() {
        RsRectangle r = new RsRectangle();
        r.insert(segment.x, segment.y);
        r.insert(segment.getX1(), segment.getY1());
        return r;
    }

    @Override
    public String getClassName() {
        return "link";
    }

    /** A one-pixel line between the nodes. */
    @Override
    public void paint(Graphics g, RsTransform t) {
        if (segment == null || lineColor == null) {
            return;
        }
        RsPoint a = t.map(segment.x, segment.y);
        RsPoint b = t.map(segment.getX1(), segment.getY1());
        g.setColor(lineColor);
        g.drawLine((int) Math.round(a.x), (int) Math.round(a.y), (int) Math.round(b.x), (int) Math.round(b.y));
    }
}
