package rp1.view;

import java.awt.Graphics;
import java.util.ArrayList;
import java.util.List;

import rp1.rossum.RsObject;
import rp1.rossum.RsPlan;
import rp1.rossum.RsTarget;
import rp1.rossum.RsTransform;
import rp1.simulator.snapshot.WorldSnapshot;

/**
 * The floor plan's objects in declaration order, drawn by their own paint methods. A target draws
 * itself only while its live selection flag is set, which the thread running the simulation may
 * change while the view draws; the layer draws a private, always-selected copy of each target instead, and leaves it
 * out when the snapshot says it was deselected, so the picture follows the snapshot alone.
 */
final class PlanLayer {
    private final List<RsObject> objects = new ArrayList<>();
    /** Per object, its index among the targets, or -1 for other objects. */
    private final List<Integer> targetIndex = new ArrayList<>();

    PlanLayer(RsPlan plan) {
        int targets = 0;
        for (RsObject o : plan.getObjectArray()) {
            if (o instanceof RsTarget t) {
                objects.add(selectedCopy(t));
                targetIndex.add(targets++);
            } else {
                objects.add(o);
                targetIndex.add(-1);
            }
        }
    }

    private static RsTarget selectedCopy(RsTarget t) {
        RsTarget copy = new RsTarget(t.getName(), null);
        if (t.isGeometrySet) {
            copy.setGeometry(t.getGeometry());
        }
        copy.lineWidth = t.lineWidth;
        copy.fillColor = t.fillColor;
        copy.lineColor = t.lineColor;
        copy.label = t.label;
        return copy;
    }

    /** Draws every object but the targets the snapshot has deselected. */
    void paint(Graphics g, RsTransform worldToPixel, WorldSnapshot snapshot) {
        for (int i = 0; i < objects.size(); i++) {
            int target = targetIndex.get(i);
            if (target < 0 || snapshot.isTargetSelected(target)) {
                objects.get(i).paint(g, worldToPixel);
            }
        }
    }
}
