package rp1.rossum;

import java.awt.Color;
import java.awt.Graphics;

/**
 * A circular body part, e.g. the chassis of a round robot. For collisions it is the 36-edge polygon
 * inscribed in the circle (first vertex at angle 0); it is drawn as a true circle and transmitted as
 * centre and radius.
 */
public class RsBodyCircle extends RsBodyShape {
    private static final long serialVersionUID = 1L;

    /** Centre, body coordinates, metres. */
    protected double refXCenter;
    /** Centre, body coordinates, metres. */
    protected double refYCenter;
    /** Radius, metres. */
    protected double refRadius;

    /** A circle centred on (xCenter, yCenter) in body coordinates. */
    public RsBodyCircle(double xCenter, double yCenter, double radius) {
        super(BodyOutline.circlePoints(xCenter, yCenter, radius), BodyOutline.CIRCLE_EDGES);
        refXCenter = xCenter;
        refYCenter = yCenter;
        refRadius = radius;
        refBounds = new RsRectangle(xCenter - radius, yCenter - radius, 2 * radius, 2 * radius);
        name = "Unnamed Circle";
    }

    /** Centre, body coordinates. */
    public double getXCenter() {
        return refXCenter;
    }

    /** Centre, body coordinates. */
    public double getYCenter() {
        return refYCenter;
    }

    /** Radius in metres. */
    public double getRadius() {
        return refRadius;
    }

    /** Fills, then outlines, the true circle in the current colours; null colours are skipped. */
    @Override
    public void paint(Graphics g, RsTransform t) {
        RsPoint c = t.map(refXCenter, refYCenter);
        int r = (int) Math.round(refRadius * t.getScale());
        int x = (int) Math.round(c.x) - r;
        int y = (int) Math.round(c.y) - r;
        Color fill = getFillColor();
        if (fill != null) {
            g.setColor(fill);
            g.fillOval(x, y, 2 * r, 2 * r);
        }
        Color line = getLineColor();
        if (line != null) {
            g.setColor(line);
            g.drawOval(x, y, 2 * r, 2 * r);
        }
    }
}
