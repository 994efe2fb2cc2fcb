package rp1.web;

import rp1.simulator.snapshot.TrailSnapshot;
import rp1.simulator.world.TrailSegment;

/**
 * One paint-trail segment in the page's encoding: its colour and width once, its points as they
 * are laid (each as the difference from the one before), and a change list of how many of them the
 * floor shows (0 once the trails are removed).
 */
final class SegmentTrack {
    private final int index;
    private final TrailSegment segment;
    private String style;
    private final StringBuilder points = new StringBuilder();
    private final StringBuilder counts = new StringBuilder();
    private int sent;
    private int shown;
    private long x;
    private long y;

    SegmentTrack(int index, TrailSnapshot t) {
        this.index = index;
        this.segment = t.segment();
        this.style = new Json().beginObject().key("c").color(t.color()).key("w").value(t.width()).endObject().toString();
    }

    TrailSegment segment() {
        return segment;
    }

    void frame(int f, TrailSnapshot t) {
        for (; sent < t.count(); sent++) {
            long nx = Encoding.metres(t.x(sent));
            long ny = Encoding.metres(t.y(sent));
            Encoding.append(points, nx - x, ny - y);
            x = nx;
            y = ny;
        }
        count(f, t.count());
    }

    void gone(int f) {
        count(f, 0);
    }

    private void count(int f, int n) {
        if (n != shown) {
            shown = n;
            Encoding.append(counts, f, n);
        }
    }

    /** Writes what changed since the last take, if anything, and forgets it. */
    void take(Json j) {
        if (style == null && points.length() == 0 && counts.length() == 0) {
            return;
        }
        j.beginObject().key("i").value(index);
        if (style != null) {
            j.key("style").raw(style);
            style = null;
        }
        j.key("pts").raw("[" + points + "]").key("n").raw("[" + counts + "]").endObject();
        points.setLength(0);
        counts.setLength(0);
    }
}
