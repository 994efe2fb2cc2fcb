package rp1.rossum;

/** Small hand-built floor plans for the body-model tests. */
final class TestPlans {
    private TestPlans() {
    }

    /** Adds an axis-aligned rectangular wall (an obstacle polygon) spanning [x0, x1] x [y0, y1]. */
    static RsWall box(RsPlan plan, String name, double x0, double y0, double x1, double y1) {
        RsWall w = new RsWall(name, plan);
        w.setGeometry(new double[] {x0, y0, x1, y0, x1, y1, x0, y1});
        plan.addObject(w);
        return w;
    }

    static RsTarget target(RsPlan plan, String name, double x, double y) {
        RsTarget t = new RsTarget(name, plan);
        t.setGeometry(new double[] {x, y, 0.05});
        plan.addObject(t);
        return t;
    }

    /** Adds rectangular floor paint spanning [x0, x1] x [y0, y1] with a region code. */
    static RsPaint paint(RsPlan plan, String name, int region, double x0, double y0, double x1, double y1) {
        RsPaint p = new RsPaint(name, plan);
        p.setGeometry(new double[] {x0, y0, x1, y0, x1, y1, x0, y1, x0, y0});
        p.setRegion(region);
        plan.addObject(p);
        return p;
    }

    /** Points of an axis-aligned rectangle [x0, x1] x [y0, y1], counter-clockwise. */
    static double[] rect(double x0, double y0, double x1, double y1) {
        return new double[] {x0, y0, x1, y0, x1, y1, x0, y1};
    }

    /** The pose with heading {@code theta} at (x, y). */
    static RsTransform pose(double x, double y, double theta) {
        return new RsTransform(theta, x, y);
    }
}
