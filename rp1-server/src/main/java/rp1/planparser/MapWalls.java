package rp1.planparser;

import java.awt.Color;
import java.util.ArrayList;
import java.util.List;

import rp1.rossum.RsPlan;
import rp1.rossum.RsWall;

/**
 * The walls of an occupancy-grid map: each rectangle of {@link OccupancyGrid#rectangles()} becomes one
 * {@link RsWall} declared by its centre line along its longer side and a thickness equal to its shorter
 * side, so the wall's polygon is exactly the rectangle's cells, placed by the map's resolution, origin
 * and yaw. Clients receive them as the walls they are.
 */
final class MapWalls {
    /** Fill and outline of map walls unless the plan says otherwise: one colour, so the merge is not drawn. */
    static final Color DEFAULT_COLOR = Color.darkGray;

    private final MapSpec spec;
    private final int rows;
    private final double cos;
    private final double sin;

    private MapWalls(MapSpec spec, int rows) {
        this.spec = spec;
        this.rows = rows;
        this.cos = Math.cos(spec.yaw());
        this.sin = Math.sin(spec.yaw());
    }

    /**
     * The walls of {@code grid}, not yet added to {@code plan}, named {@code prefix_1}, {@code prefix_2},
     * ... in the order of the cover, or unnamed (for the plan to name) if {@code prefix} is null.
     */
    static List<RsWall> of(OccupancyGrid grid, MapSpec spec, RsPlan plan, String prefix, Color fill, Color line) {
        MapWalls placer = new MapWalls(spec, grid.height());
        List<RsWall> walls = new ArrayList<>();
        for (OccupancyGrid.Cells c : grid.rectangles()) {
            RsWall w = new RsWall(prefix == null ? null : prefix + "_" + (walls.size() + 1), plan);
            w.setGeometry(placer.centreLine(c));
            w.setFillColor(fill);
            w.setLineColor(line);
            walls.add(w);
        }
        return walls;
    }

    /**
     * Null if the whole image lies within {@link ParserLimits#MAX_COORDINATE} of the origin, else what
     * reaches beyond it, for a message.
     */
    static String outOfRange(OccupancyGrid grid, MapSpec spec) {
        MapWalls placer = new MapWalls(spec, grid.height());
        double[] corners = {0, 0, grid.width(), 0, grid.width(), grid.height(), 0, grid.height()};
        for (int i = 0; i < corners.length; i += 2) {
            double[] p = placer.place(corners[i], corners[i + 1]);
            if (!(Math.abs(p[0]) <= ParserLimits.MAX_COORDINATE && Math.abs(p[1]) <= ParserLimits.MAX_COORDINATE)) {
                return "the image (" + grid.width() + " × " + grid.height() + " pixels of " + spec.resolution()
                        + " m) has a corner at (" + p[0] + ", " + p[1] + ") m, beyond " + ValueReader.LIMIT_IN_WORDS;
            }
        }
        return null;
    }

    /** {@code x0, y0, x1, y1, thickness} of the rectangle's wall, in the plan. */
    private double[] centreLine(OccupancyGrid.Cells c) {
        double left = c.column();
        double right = c.column() + c.width();
        double bottom = rows - c.row() - c.height();
        double top = rows - c.row();
        double[] a;
        double[] b;
        double thickness;
        if (c.width() >= c.height()) {
            double middle = (bottom + top) / 2;
            a = place(left, middle);
            b = place(right, middle);
            thickness = c.height();
        } else {
            double middle = (left + right) / 2;
            a = place(middle, bottom);
            b = place(middle, top);
            thickness = c.width();
        }
        return new double[] {a[0], a[1], b[0], b[1], thickness * spec.resolution()};
    }

    /** A point in pixels from the image's lower-left corner (x right, y up), in the plan's metres. */
    private double[] place(double x, double y) {
        double mx = x * spec.resolution();
        double my = y * spec.resolution();
        return new double[] {spec.originX() + cos * mx - sin * my, spec.originY() + sin * mx + cos * my};
    }
}
