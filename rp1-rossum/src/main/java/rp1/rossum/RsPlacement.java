package rp1.rossum;

import java.awt.Color;
import java.awt.Graphics;

/**
 * A named starting pose for robots ("home"), drawn as a home-plate pentagon pointing along its
 * orientation. Geometry: {@code x, y, orientation (radians), radius}; the radius is only for drawing.
 */
public class RsPlacement extends RsObject {
    /** Home-plate outline in placement-local units (x forward, y left), scaled by the pixel radius. */
    private static final double[][] PLATE = {
        {1.0, 0.0}, {0.6, 0.8485}, {-0.8485, 0.8485}, {-0.8485, -0.8485}, {0.6, -0.8485}};

    /** Position, metres. */
    public double x;
    /** Position, metres. */
    public double y;
    /** Radians, exactly as given (not normalized). */
    public double orientation;
    /** Radius of the drawn plate, metres (only for drawing). */
    public double radius;
    /** Width of the drawn ring in pixels; below 2 a thin outline is drawn. */
    public int lineWidth;

    /**
     * A placement called {@code name} of {@code plan}, without a pose yet; drawn in dark grey.
     *
     * @param name the placement's name, or null to have the plan name it
     * @param plan the plan it belongs to
     */
    public RsPlacement(String name, RsPlan plan) {
        super(name, plan);
        fillColor = Color.darkGray;
        lineColor = Color.darkGray;
    }

    /** {@code x, y, orientation (radians), radius}; any other count leaves the geometry unset. */
    @Override
    public void setGeometry(double[] g) {
        if (g == null || g.length != 4) {
            isGeometrySet = false;
            return;
        }
        x = g[0];
        y = g[1];
        orientation = g[2];
        radius = g[3];
        isGeometrySet = true;
    }

    /** {@code x, y, orientation, radius}, as transmitted. */
    @Override
    public double[] getGeometry() {
        return new double[] {x, y, orientation, radius};
    }

    @Override
    protected RsRectangle computeBounds() {
        return new RsRectangle(x - radius, y - radius, 2 * radius, 2 * radius);
    }

    @Override
    public String getClassName() {
        return "placement";
    }

    /** The home plate (a ring when wide enough, else an outline), then the label or a "+". */
    @Override
    public void paint(Graphics g, RsTransform t) {
        if (!isGeometrySet || lineColor == null) {
            return;
        }
        double scale = t.getScale();
        double s = radius * scale;
        if (Math.round(s) <= 0) {
            return;
        }
        RsPoint c = t.map(x, y);
        g.setColor(lineColor);
        if (lineWidth >= 2 && s > 4 * lineWidth) {
            fillPlate(g, t, radius);
            g.setColor(Color.white);
            fillPlate(g, t, (s - lineWidth) / scale);
        } else {
            int[][] p = plate(t, radius);
            g.drawPolygon(p[0], p[1], PLATE.length);
        }
        PlanLabels.labelOrCross(g, label, (int) Math.round(c.x), (int) Math.round(c.y), lineColor);
    }

    private void fillPlate(Graphics g, RsTransform t, double size) {
        int[][] p = plate(t, size);
        g.fillPolygon(p[0], p[1], PLATE.length);
    }

    private int[][] plate(RsTransform t, double size) {
        RsTransform local = new RsTransform(t, new RsTransform(orientation, x, y));
        int[] xs = new int[PLATE.length];
        int[] ys = new int[PLATE.length];
        for (int i = 0; i < PLATE.length; i++) {
            local.iMapArrayIndex(size * PLATE[i][0], size * PLATE[i][1], i, xs, ys);
        }
        return new int[][] {xs, ys};
    }
}
