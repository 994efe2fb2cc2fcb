package rp1.web;

import rp1.rossum.RsNavLink;
import rp1.rossum.RsNavNode;
import rp1.rossum.RsObject;
import rp1.rossum.RsPaint;
import rp1.rossum.RsPlacement;
import rp1.rossum.RsPlan;
import rp1.rossum.RsRectangle;
import rp1.rossum.RsSegment;
import rp1.rossum.RsTarget;
import rp1.rossum.RsWall;

/**
 * The floor plan as the page draws it (docs/recording.md, "The replay page"): its objects in
 * declaration order, each with what the window's painter of that kind of object uses — outlines and
 * colours of walls and paint, centre, radius, line width and label of targets and placements, nodes
 * and links. Targets carry their index among the targets, by which the run's selection changes
 * name them.
 */
final class PlanJson {
    private PlanJson() {
    }

    /** The plan's caption, bounds and objects, as members of an object being written. */
    static void write(Json j, RsPlan plan) {
        RsRectangle b = plan.getBounds();
        j.key("caption").value(plan.getCaption());
        j.key("bounds").beginArray().value(b.x).value(b.y).value(b.width).value(b.height).endArray();
        j.key("plan").beginArray();
        int targets = 0;
        for (RsObject o : plan.getObjectArray()) {
            if (o instanceof RsWall w) {
                polygon(j, "wall", w.getSegmentArray(), o);
            } else if (o instanceof RsPaint p) {
                polygon(j, "paint", p.getSegmentArray(), o);
            } else if (o instanceof RsTarget t) {
                j.beginObject().key("k").value("target").key("i").value(targets++).key("name").value(t.getName());
                point(j, t.isGeometrySet, t.x, t.y, o);
                j.key("r").value(t.radius).key("w").value(t.lineWidth).endObject();
            } else if (o instanceof RsPlacement p) {
                j.beginObject().key("k").value("placement");
                point(j, p.isGeometrySet, p.x, p.y, o);
                j.key("r").value(p.radius).key("w").value(p.lineWidth).key("o").value(p.orientation).endObject();
            } else if (o instanceof RsNavNode n) {
                j.beginObject().key("k").value("node");
                point(j, n.isGeometrySet, n.x, n.y, o);
                j.endObject();
            } else if (o instanceof RsNavLink l && l.segment != null) {
                j.beginObject().key("k").value("link").key("xy").beginArray().value(l.segment.x).value(l.segment.y)
                        .value(l.segment.getX1()).value(l.segment.getY1()).endArray();
                colours(j, o);
                j.endObject();
            }
        }
        j.endArray();
    }

    private static void polygon(Json j, String kind, RsSegment[] edges, RsObject o) {
        if (edges == null) {
            return;
        }
        j.beginObject().key("k").value(kind).key("xy").beginArray();
        for (RsSegment e : edges) {
            j.value(e.x).value(e.y);
        }
        j.endArray();
        colours(j, o);
        j.endObject();
    }

    private static void point(Json j, boolean set, double x, double y, RsObject o) {
        j.key("set").value(set).key("x").value(x).key("y").value(y).key("label").value(o.label);
        colours(j, o);
    }

    private static void colours(Json j, RsObject o) {
        j.key("f").color(o.fillColor).key("l").color(o.lineColor);
    }
}
