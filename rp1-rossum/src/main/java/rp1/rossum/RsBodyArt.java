package rp1.rossum;

import java.awt.Color;
import java.awt.Graphics;

/**
 * Decoration drawn with the robot: a polyline (lettering, markings) in the line colour. It never
 * interacts with walls or sensors and, as in RP1 0.60, cannot be transmitted to the simulator: a
 * body specification leaves it out.
 */
public class RsBodyArt extends RsBodyPart {
    private static final long serialVersionUID = 1L;

    private double[] points;

    /**
     * Art through the first {@code nPointList} points of {@code pointList} (x0, y0, x1, y1, ...),
     * body coordinates.
     *
     * @throws IllegalArgumentException if nPointList is negative or the array is too short
     */
    public RsBodyArt(double[] pointList, int nPointList) {
        if (nPointList < 0 || nPointList > 0 && (pointList == null || pointList.length < 2 * nPointList)) {
            throw new IllegalArgumentException("pointList does not hold nPointList=" + nPointList + " points");
        }
        points = new double[2 * nPointList];
        if (nPointList > 0) {
            System.arraycopy(pointList, 0, points, 0, points.length);
        }
        updateBounds();
    }

    /**
     * Moves the art: rotates it by {@code theta} radians about the body origin, scales it by
     * {@code scale}, then shifts it by ({@code dx}, {@code dy}).
     */
    public void transform(double theta, double scale, double dx, double dy) {
        double c = scale * Math.cos(theta);
        double s = scale * Math.sin(theta);
        for (int i = 0; i < points.length; i += 2) {
            double x = points[i];
            double y = points[i + 1];
            points[i] = c * x - s * y + dx;
            points[i + 1] = s * x + c * y + dy;
        }
        updateBounds();
    }

    /** A copy of the points x0, y0, x1, y1, ... */
    public double[] getPoints() {
        return points.clone();
    }

    private void updateBounds() {
        refBounds = new RsRectangle();
        for (int i = 0; i < points.length; i += 2) {
            refBounds.insert(points[i], points[i + 1]);
        }
    }

    /** Draws the polyline in the current line colour (nothing if it is null). */
    @Override
    public void paint(Graphics g, RsTransform t) {
        Color line = getLineColor();
        int n = points.length / 2;
        if (line == null || n < 2) {
            return;
        }
        int[] xs = new int[n];
        int[] ys = new int[n];
        for (int i = 0; i < n; i++) {
            t.iMapArrayIndex(points[2 * i], points[2 * i + 1], i, xs, ys);
        }
        g.setColor(line);
        g.drawPolyline(xs, ys, n);
    }
}
