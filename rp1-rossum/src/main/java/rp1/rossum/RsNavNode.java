package rp1.rossum;

import java.awt.Color;
import java.awt.Graphics;
import java.util.Arrays;

/**
 * A node of the floor plan's navigation network: a point ("intersection") joined to other nodes by
 * {@link RsNavLink}s ("roads"). Clients can plan routes over the network. Geometry: {@code x, y}.
 */
public class RsNavNode extends RsObject {
    /** Half the side of the box a node covers in the plan's extent, metres. */
    private static final double HALF_EXTENT = 0.005;

    /** The links attached to this node, in the order they were declared. */
    public RsNavLink[] link = new RsNavLink[0];
    /** Free for route-planning clients to mark the node. */
    public boolean visited;
    /** Position, metres. */
    public double x;
    /** Position, metres. */
    public double y;

    /**
     * A node called {@code name} of {@code plan}, without a position yet; drawn in cyan.
     *
     * @param name the node's name, or null to have the plan name it
     * @param plan the plan it belongs to
     */
    public RsNavNode(String name, RsPlan plan) {
        super(name, plan);
        fillColor = Color.cyan;
        lineColor = Color.cyan;
    }

    /** {@code x, y}; any other count leaves the geometry unset. */
    @Override
    public void setGeometry(double[] g) {
        if (g == null || g.length != 2) {
            isGeometrySet = false;
            return;
        }
        x = g[0];
        y = g[1];
        isGeometrySet = true;
    }

    @Override
    public double[] getGeometry() {
        return new double[] {x, y};
    }

    @Override
    public void setLabel(String label) {
        this.label = label;
    }

    /**
     * The node's label, drawn next to it.
     *
     * @return the label, or null
     */
    public String getLabel() {
        return label;
    }

    @Override
    protected RsRectangle computeBounds() {
        return new RsRectangle(x - HALF_EXTENT, y - HALF_EXTENT, 2 * HALF_EXTENT, 2 * HALF_EXTENT);
    }

    @Override
    public String getClassName() {
        return "node";
    }

    /** Attaches a link to this node. */
    public void addLink(RsNavLink l) {
        link = Arrays.copyOf(link, link.length + 1);
        link[link.length - 1] = l;
    }

    /** A 3 x 3 pixel square, with the label just right of and below it. */
    @Override
    public void paint(Graphics g, RsTransform t) {
        if (!isGeometrySet || lineColor == null) {
            return;
        }
        RsPoint p = t.map(x, y);
        int px = (int) Math.round(p.x);
        int py = (int) Math.round(p.y);
        g.setColor(lineColor);
        g.drawRect(px - 1, py - 1, 2, 2);
        if (label != null && !label.isEmpty()) {
            g.setFont(PlanLabels.LABEL_FONT);
            g.drawString(label, px + 3, py + 3 + g.getFontMetrics().getAscent());
        }
    }
}
