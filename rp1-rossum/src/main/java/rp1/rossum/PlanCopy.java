package rp1.rossum;

import java.util.HashMap;
import java.util.Map;

/**
 * Copies a plan's objects for {@link RsPlan#copy()}: every field as it is, with no geometry computed
 * again (a segment built from its ends differs from the original by rounding), each mutable part (a
 * segment, a polygon, bounds, the navigation network's links between nodes) a new one. Only the plan's
 * own types can be copied: a subclass may hold fields this cannot know of.
 */
final class PlanCopy {
    private final RsPlan to;
    /** The copy of each node and link met so far, so that links and nodes point at the copies. */
    private final Map<RsObject, RsObject> copies = new HashMap<>();

    PlanCopy(RsPlan to) {
        this.to = to;
    }

    /**
     * The copy of {@code o}, belonging to the new plan (made on first use).
     *
     * @throws IllegalStateException if {@code o} is not of one of the plan's own types
     */
    RsObject of(RsObject o) {
        RsObject done = copies.get(o);
        if (done != null) {
            return done;
        }
        RsObject copy;
        Class<?> type = o.getClass();
        if (type == RsWall.class) {
            copy = wall((RsWall) o);
        } else if (type == RsTarget.class) {
            copy = target((RsTarget) o);
        } else if (type == RsPlacement.class) {
            copy = placement((RsPlacement) o);
        } else if (type == RsPaint.class) {
            copy = paint((RsPaint) o);
        } else if (type == RsNavNode.class) {
            copy = node((RsNavNode) o);
        } else if (type == RsNavLink.class) {
            copy = link((RsNavLink) o);
        } else {
            throw new IllegalStateException("cannot copy a plan holding a " + type.getName() + " (" + o.getName() + ")");
        }
        return copy;
    }

    private RsWall wall(RsWall w) {
        RsWall c = remember(w, new RsWall(null, to));
        c.x0 = w.x0;
        c.y0 = w.y0;
        c.x1 = w.x1;
        c.y1 = w.y1;
        c.thickness = w.thickness;
        c.polygon = polygon(w.polygon);
        c.segmentArray = outline(w.segmentArray, w.polygon, c.polygon);
        return c;
    }

    private RsPaint paint(RsPaint p) {
        RsPaint c = remember(p, new RsPaint(null, to));
        c.region = p.region;
        c.polygon = polygon(p.polygon);
        c.segmentArray = outline(p.segmentArray, p.polygon, c.polygon);
        return c;
    }

    private RsTarget target(RsTarget t) {
        RsTarget c = remember(t, new RsTarget(null, to));
        c.x = t.x;
        c.y = t.y;
        c.radius = t.radius;
        c.lineWidth = t.lineWidth;
        return c;
    }

    private RsPlacement placement(RsPlacement p) {
        RsPlacement c = remember(p, new RsPlacement(null, to));
        c.x = p.x;
        c.y = p.y;
        c.orientation = p.orientation;
        c.radius = p.radius;
        c.lineWidth = p.lineWidth;
        return c;
    }

    private RsNavNode node(RsNavNode n) {
        RsNavNode c = remember(n, new RsNavNode(null, to));
        c.x = n.x;
        c.y = n.y;
        c.visited = n.visited;
        RsNavLink[] links = new RsNavLink[n.link.length];
        for (int i = 0; i < links.length; i++) {
            links[i] = n.link[i] == null ? null : (RsNavLink) of(n.link[i]);
        }
        c.link = links;
        return c;
    }

    private RsNavLink link(RsNavLink l) {
        RsNavLink c = remember(l, new RsNavLink(null, to));
        c.visited = l.visited;
        c.segment = l.segment == null ? null : segment(l.segment);
        c.n0 = l.n0 == null ? null : (RsNavNode) of(l.n0);
        c.n1 = l.n1 == null ? null : (RsNavNode) of(l.n1);
        return c;
    }

    /** Files the copy before its links are followed (a node's links lead back to it) and gives it the common fields. */
    private <T extends RsObject> T remember(RsObject original, T copy) {
        original.copyCommonTo(copy);
        copies.put(original, copy);
        return copy;
    }

    /**
     * The copy of a wall's or paint's {@code segments}: its polygon's copied edges when they are the
     * polygon's own (as a parsed plan's are), so that the copy shares them as the original does.
     */
    private static RsSegment[] outline(RsSegment[] segments, RsPolygon polygon, RsPolygon copied) {
        if (segments == null) {
            return null;
        }
        return polygon != null && segments == polygon.segment ? copied.segment : segments(segments);
    }

    private static RsPolygon polygon(RsPolygon p) {
        return p == null ? null : new RsPolygon(p, segments(p.segment));
    }

    private static RsSegment[] segments(RsSegment[] s) {
        RsSegment[] c = new RsSegment[s.length];
        for (int i = 0; i < s.length; i++) {
            c[i] = s[i] == null ? null : segment(s[i]);
        }
        return c;
    }

    /** A segment with the original's numbers, its direction and length included, to the bit. */
    private static RsSegment segment(RsSegment s) {
        RsSegment c = new RsSegment();
        c.x = s.x;
        c.y = s.y;
        c.v.x = s.v.x;
        c.v.y = s.v.y;
        c.m = s.m;
        return c;
    }
}
