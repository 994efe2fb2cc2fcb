package rp1.rossum;

import java.awt.Color;
import java.awt.Graphics;

/**
 * A target: a point source that target sensors detect (a candle in the fire-fighting contest). The
 * radius is only for drawing. Targets start selected; deselected targets are neither sensed nor
 * drawn. Geometry: {@code x, y, radius}.
 */
public class RsTarget extends RsObject {
    /** Position of the centre, metres. */
    public double x;
    /** Position of the centre, metres. */
    public double y;
    /** Radius, metres (only for drawing; sensors see the centre). */
    public double radius;
    /** Width of the drawn ring in pixels; below 2 a thin circle is drawn. */
    public int lineWidth;

    /**
     * A target called {@code name} of {@code plan}, selected, without a position yet.
     *
     * @param name the target's name, or null to have the plan name it
     * @param plan the plan it belongs to
     */
    public RsTarget(String name, RsPlan plan) {
        super(name, plan);
        fillColor = Color.lightGray;
        lineColor = Color.lightGray;
    }

    /** {@code x, y, radius} in metres; any other count leaves the geometry unset. */
    @Override
    public void setGeometry(double[] g) {
        if (g == null || g.length != 3) {
            isGeometrySet = false;
            return;
        }
        x = g[0];
        y = g[1];
        radius = g[2];
        isGeometrySet = true;
    }

    /** {@code x, y, radius}, as transmitted. */
    @Override
    public double[] getGeometry() {
        return new double[] {x, y, radius};
    }

    @Override
    protected RsRectangle computeBounds() {
        return new RsRectangle(x - radius, y - radius, 2 * radius, 2 * radius);
    }

    @Override
    public String getClassName() {
        return "target";
    }

    /** A ring (or thin circle) around the point, then the label or a "+" on it. */
    @Override
    public void paint(Graphics g, RsTransform t) {
        if (!selected || !isGeometrySet) {
            return;
        }
        RsPoint c = t.map(x, y);
        int px = (int) Math.round(c.x);
        int py = (int) Math.round(c.y);
        int r = (int) Math.round(radius * t.getScale());
        Color labelColor = lineColor;
        if (r > 0 && lineColor != null) {
            g.setColor(lineColor);
            if (lineWidth >= 2 && r > 4 * lineWidth) {
                g.fillOval(px - r, py - r, 2 * r, 2 * r);
                int inner = r - lineWidth;
                g.setColor(Color.white);
                g.fillOval(px - inner, py - inner, 2 * inner, 2 * inner);
                labelColor = fillColor;
            } else {
                g.drawOval(px - r, py - r, 2 * r, 2 * r);
            }
        }
        PlanLabels.labelOrCross(g, label, px, py, labelColor);
    }
}
