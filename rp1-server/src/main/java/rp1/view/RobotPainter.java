package rp1.view;

import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.Polygon;
import java.awt.Shape;
import java.awt.geom.Ellipse2D;

import rp1.rossum.RsBodyCircle;
import rp1.rossum.RsBodyPart;
import rp1.rossum.RsBodyShape;
import rp1.rossum.RsPoint;
import rp1.rossum.RsTransform;
import rp1.rossum.RsWheel;
import rp1.simulator.snapshot.PartSnapshot;
import rp1.simulator.snapshot.RobotSnapshot;

/**
 * Draws a robot from its snapshot (behavior.md section 10): the parts in body order, each filled and
 * outlined in its hot colours if the snapshot has it hot, else in its cold ones (a null colour is
 * not drawn); circles as true circles; wheels turned about their hubs by the snapshot's steering
 * angle. The parts' own paint methods read the live hot flag and steering, which the scheduler
 * thread keeps changing, so they are not used here. A robot whose wheels slip (behavior.md section
 * 8.9) is drawn over a grey outline of its body where it believes it is.
 */
final class RobotPainter {
    private RobotPainter() {
    }

    /** The outline of a robot where it believes it is. */
    private static final Color BELIEF = new Color(150, 150, 150);

    static void paint(Graphics2D g, RobotSnapshot robot, RsTransform worldToPixel) {
        RsTransform belief = robot.believedPose();
        if (belief != null) {
            paintBelief(g, robot, new RsTransform(worldToPixel, belief));
        }
        RsTransform bodyToPixel = new RsTransform(worldToPixel, robot.pose());
        for (PartSnapshot p : robot.parts()) {
            paintPart(g, p, bodyToPixel);
        }
    }

    /** Every shape's outline, unfilled, unsteered. */
    private static void paintBelief(Graphics2D g, RobotSnapshot robot, RsTransform bodyToPixel) {
        for (PartSnapshot p : robot.parts()) {
            if (p.part() instanceof RsBodyCircle c) {
                circle(g, bodyToPixel, c, null, BELIEF);
            } else if (p.part() instanceof RsBodyShape s) {
                polygon(g, bodyToPixel, s.getOutlineVertices(), null, BELIEF);
            }
        }
    }

    private static void paintPart(Graphics2D g, PartSnapshot p, RsTransform t) {
        RsBodyPart part = p.part();
        Color fill = p.hot() ? part.getHotFillColor() : part.getColdFillColor();
        Color line = p.hot() ? part.getHotLineColor() : part.getColdLineColor();
        if (part instanceof RsBodyCircle c) {
            circle(g, t, c, fill, line);
        } else if (part instanceof RsWheel w) {
            RsTransform steered = new RsTransform(t, RsTransform.rotationAbout(p.steering(), w.getX(), w.getY()));
            polygon(g, steered, w.getOutlineVertices(), fill, line);
        } else if (part instanceof RsBodyShape s) {
            polygon(g, t, s.getOutlineVertices(), fill, line);
        }
    }

    private static void circle(Graphics2D g, RsTransform t, RsBodyCircle c, Color fill, Color line) {
        RsPoint centre = t.map(c.getXCenter(), c.getYCenter());
        int r = (int) Math.round(c.getRadius() * t.getScale());
        int x = (int) Math.round(centre.x) - r;
        int y = (int) Math.round(centre.y) - r;
        fillAndOutline(g, new Ellipse2D.Double(x, y, 2 * r, 2 * r), fill, line);
    }

    private static void polygon(Graphics2D g, RsTransform t, double[] xy, Color fill, Color line) {
        int n = xy.length / 2;
        if (n == 0) {
            return;
        }
        int[] xs = new int[n];
        int[] ys = new int[n];
        for (int i = 0; i < n; i++) {
            t.iMapArrayIndex(xy[2 * i], xy[2 * i + 1], i, xs, ys);
        }
        fillAndOutline(g, new Polygon(xs, ys, n), fill, line);
    }

    /** Fills {@code shape}, then outlines it; a null colour is not drawn. */
    private static void fillAndOutline(Graphics2D g, Shape shape, Color fill, Color line) {
        if (fill != null) {
            g.setColor(fill);
            g.fill(shape);
        }
        if (line != null) {
            g.setColor(line);
            g.draw(shape);
        }
    }
}
