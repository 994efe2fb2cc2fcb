package rp1.rossum;

import java.awt.Color;
import java.awt.Graphics;

/** Polygon helpers shared by the polygonal plan objects ({@link RsWall}, {@link RsPaint}). */
final class PlanPolygons {
    private PlanPolygons() {
    }

    /**
     * The polygon through vertices x0, y0, x1, y1, ... (a repeated first vertex is dropped), or null
     * if there are fewer than three vertices, an odd count, or no area.
     */
    static RsPolygon toPolygon(double[] xy) {
        if (xy == null || xy.length < 6 || xy.length % 2 != 0) {
            return null;
        }
        try {
            return new RsPolygon(xy, xy.length / 2);
        } catch (RsPolygonException e) {
            return null;
        }
    }

    /** The start points of the edges: x0, y0, x1, y1, ... without repeating the first. */
    static double[] openVertices(RsSegment[] edges) {
        if (edges == null) {
            return new double[0];
        }
        double[] xy = new double[2 * edges.length];
        for (int i = 0; i < edges.length; i++) {
            xy[2 * i] = edges[i].x;
            xy[2 * i + 1] = edges[i].y;
        }
        return xy;
    }

    /** Fills the outline in {@code fill} and draws it in {@code line}; null colours are not drawn. */
    static void paint(Graphics g, RsTransform t, RsSegment[] edges, Color fill, Color line) {
        if (edges == null) {
            return;
        }
        int n = edges.length;
        int[] xs = new int[n];
        int[] ys = new int[n];
        for (int i = 0; i < n; i++) {
            t.iMapArrayIndex(edges[i].x, edges[i].y, i, xs, ys);
        }
        if (fill != null) {
            g.setColor(fill);
            g.fillPolygon(xs, ys, n);
        }
        if (line != null) {
            g.setColor(line);
            g.drawPolygon(xs, ys, n);
        }
    }
}
