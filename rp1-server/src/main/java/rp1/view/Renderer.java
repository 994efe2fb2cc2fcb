package rp1.view;

import java.awt.Color;
import java.awt.Graphics2D;

import rp1.rossum.RsPlan;
import rp1.rossum.RsTransform;
import rp1.simulator.snapshot.RobotSnapshot;
import rp1.simulator.snapshot.TrailSnapshot;
import rp1.simulator.snapshot.WorldSnapshot;

/**
 * Draws a world snapshot (behavior.md section 10): a white canvas, the plan's objects in declaration
 * order (deselected targets left out), then the paint trails, then every placed robot on top. The
 * picture depends on the snapshot and the view transform only, never on the live world, so the
 * window and picture files can draw on their own threads. Immutable and thread-safe.
 */
public final class Renderer {
    private final RsPlan plan;
    private final PlanLayer planLayer;

    /** A renderer for snapshots of worlds on {@code plan}. */
    public Renderer(RsPlan plan) {
        this.plan = plan;
        this.planLayer = new PlanLayer(plan);
    }

    /** The plan this renderer draws. */
    public RsPlan getPlan() {
        return plan;
    }

    /**
     * Draws {@code snapshot} onto {@code g}, whose canvas is the transform's size.
     *
     * @throws IllegalArgumentException if the snapshot is of another plan
     */
    public void render(WorldSnapshot snapshot, Graphics2D g, ViewTransform view) {
        if (snapshot.plan() != plan) {
            throw new IllegalArgumentException("snapshot of another plan: " + snapshot.plan().getCaption());
        }
        g.setColor(Color.white);
        g.fillRect(0, 0, view.getWidth(), view.getHeight());
        RsTransform worldToPixel = view.worldToPixel();
        planLayer.paint(g, worldToPixel, snapshot);
        for (TrailSnapshot t : snapshot.trails()) {
            TrailPainter.paint(g, t, worldToPixel);
        }
        for (RobotSnapshot r : snapshot.placedRobots()) {
            RobotPainter.paint(g, r, worldToPixel);
        }
    }

    /** Draws {@code snapshot} with the plan fitted into a canvas of {@code width} by {@code height}. */
    public void render(WorldSnapshot snapshot, Graphics2D g, int width, int height) {
        render(snapshot, g, ViewTransform.fit(plan.getBounds(), width, height));
    }
}
