package rp1.view;

import java.awt.BasicStroke;
import java.awt.Graphics2D;
import java.awt.Stroke;
import java.awt.geom.Path2D;

import rp1.rossum.RsTransform;
import rp1.simulator.snapshot.TrailSnapshot;

/**
 * Draws a paint trail (behavior.md section 9): a 1-pixel polyline in the trail's colour, and when
 * the trail is at least 2 pixels wide also a band of that width along it, each piece a quadrilateral
 * with a bevel wedge filling each joint.
 */
final class TrailPainter {
    private TrailPainter() {
    }

    static void paint(Graphics2D g, TrailSnapshot trail, RsTransform worldToPixel) {
        int n = trail.count();
        if (n < 2 || trail.color() == null) {
            return;
        }
        g.setColor(trail.color());
        double pixelWidth = trail.width() * worldToPixel.getScale();
        if (pixelWidth >= 2.0) {
            Stroke previous = g.getStroke();
            g.setStroke(new BasicStroke((float) pixelWidth, BasicStroke.CAP_BUTT, BasicStroke.JOIN_BEVEL));
            g.draw(path(trail, worldToPixel));
            g.setStroke(previous);
        }
        int[] xs = new int[n];
        int[] ys = new int[n];
        for (int i = 0; i < n; i++) {
            worldToPixel.iMapArrayIndex(trail.x(i), trail.y(i), i, xs, ys);
        }
        g.drawPolyline(xs, ys, n);
    }

    private static Path2D path(TrailSnapshot trail, RsTransform t) {
        Path2D.Double p = new Path2D.Double();
        for (int i = 0; i < trail.count(); i++) {
            double x = trail.x(i);
            double y = trail.y(i);
            double px = t.m11 * x + t.m12 * y + t.m13;
            double py = t.m21 * x + t.m22 * y + t.m23;
            if (i == 0) {
                p.moveTo(px, py);
            } else {
                p.lineTo(px, py);
            }
        }
        return p;
    }
}
