package rp1.planparser;

import java.io.IOException;

import rp1.rossum.RsObject;
import rp1.rossum.RsPaint;
import rp1.rossum.RsPlan;
import rp1.rossum.RsWall;

/**
 * {@code obstacle} (stored as a wall) and {@code paint}: a polygon given either by its vertices
 * ({@code geometry: x1, y1, x2, y2, x3, y3, ...;}) or as a regular polygon ({@code polygon: sides,
 * radius;}), then rotated about the origin by {@code orientation} degrees and moved by {@code offset}.
 * The polygon must be simple. Paint also takes {@code region}.
 */
final class PolygonDeclaration extends Declaration {
    private static final int MIN_SIDES = 3;
    private static final int MAX_SIDES = 256;
    private static final double MIN_RADIUS = 0.005;
    private static final double MAX_RADIUS = 10_000.0;

    private final boolean paint;
    private double[] vertices;
    private Token shapeItem;
    private Token polygonItem;
    private Token geometryItem;
    private double offsetX;
    private double offsetY;
    private double orientationDegrees;

    private PolygonDeclaration(RsObject object, boolean paint) {
        super(object, true, "geometry, polygon, offset, orientation" + (paint ? ", region" : ""));
        this.paint = paint;
    }

    /** An {@code obstacle} declaration. */
    static PolygonDeclaration obstacle(String name, RsPlan plan) {
        return new PolygonDeclaration(new RsWall(name, plan), false);
    }

    /** A {@code paint} declaration. */
    static PolygonDeclaration paint(String name, RsPlan plan) {
        return new PolygonDeclaration(new RsPaint(name, plan), true);
    }

    @Override
    String keyword() {
        return paint ? "paint" : "obstacle";
    }

    @Override
    protected boolean specificItem(Token item, ValueReader in) throws IOException, RsParsingException {
        switch (item.text()) {
            case "geometry":
                geometry(item, in);
                return true;
            case "polygon":
                polygon(item, in);
                return true;
            case "offset":
                NumberList d = in.numbers(2, "Invalid number of parameters in numeric specification", "dx, dy");
                offsetX = in.length(d, 0);
                offsetY = in.length(d, 1);
                return true;
            case "orientation":
                orientationDegrees = in.numbers(1, "Invalid number of parameters in numeric specification",
                        "degrees").values()[0];
                return true;
            case "region":
                if (!paint) {
                    return false;
                }
                int region = in.integer("Invalid syntax where integer region specification expected").integer();
                ((RsPaint) object).setRegion(region);
                return true;
            default:
                return false;
        }
    }

    private void geometry(Token item, ValueReader in) throws IOException, RsParsingException {
        NumberList list = in.numbers();
        double[] v = list.values();
        if (v.length < 2 * MIN_SIDES || v.length % 2 != 0) {
            throw in.lexer().error(list.end(), "Invalid number of parameters in geometry specification (need at"
                    + " least 3 coordinate pairs): expected an even count of 6 or more, found " + v.length);
        }
        checkNotBoth(polygonItem, item, in);
        vertices = in.lengths(list);
        geometryItem = item;
        shapeItem = item;
    }

    private void polygon(Token item, ValueReader in) throws IOException, RsParsingException {
        Token sides = in.integer("Invalid syntax where integer number-of-sides expected");
        int n = sides.integer();
        if (n < MIN_SIDES || n > MAX_SIDES) {
            throw in.lexer().error(sides, "Polygon number-of-sides must be in range 3 through 256, found " + n);
        }
        in.symbol(',', "Invalid syntax where comma expected after the number of sides");
        Token r = in.lexer().nextInStatement();
        if (!r.isNumber()) {
            throw in.lexer().error(r, "Invalid syntax where radius expected (a positive number), found "
                    + r.describe());
        }
        double radius = in.length(r.number(), r);
        if (radius < MIN_RADIUS || radius > MAX_RADIUS) {
            throw in.lexer().error(r, "Radius must be in range 0.5 cm to 10 km, found " + r.text());
        }
        checkNotBoth(geometryItem, item, in);
        vertices = regularPolygon(n, radius);
        polygonItem = item;
        shapeItem = item;
    }

    private void checkNotBoth(Token other, Token item, ValueReader in) throws RsParsingException {
        if (other != null) {
            throw in.lexer().error(item, (paint ? "Paint" : "Obstacle") + " declaration must not specify both"
                    + " polygon and geometry (the other was given on line " + other.line() + ")");
        }
    }

    /** N vertices on a circle about the origin, the first on +x, anticlockwise. */
    private static double[] regularPolygon(int n, double radius) {
        double[] xy = new double[2 * n];
        for (int k = 0; k < n; k++) {
            double a = 2.0 * Math.PI * k / n;
            xy[2 * k] = radius * Math.cos(a);
            xy[2 * k + 1] = radius * Math.sin(a);
        }
        return xy;
    }

    @Override
    RsObject finish(Token close, PlanLexer lexer) throws RsParsingException {
        if (vertices == null) {
            throw lexer.error(close, "Missing or invalid geometry specification: " + (paint ? "paint" : "an obstacle")
                    + " needs geometry: x1, y1, x2, y2, x3, y3, ...; or polygon: sides, radius;");
        }
        double[] xy = SimplePolygon.dropClosingVertex(placed());
        String crossing = SimplePolygon.findViolation(xy);
        if (crossing != null) {
            throw lexer.error(shapeItem, "Polygon is not simple: " + crossing
                    + " (vertices numbered from 1; the polygon must not intersect itself)");
        }
        object.setGeometry(xy);
        if (!object.isGeometrySet) {
            throw lexer.error(shapeItem, "Missing or invalid geometry specification: the polygon has no area");
        }
        return object;
    }

    /** The vertices rotated about the origin by the orientation, then moved by the offset. */
    private double[] placed() {
        double a = Math.toRadians(orientationDegrees);
        double cos = Math.cos(a);
        double sin = Math.sin(a);
        double[] xy = new double[vertices.length];
        for (int i = 0; i < xy.length; i += 2) {
            double x = vertices[i];
            double y = vertices[i + 1];
            xy[i] = cos * x - sin * y + offsetX;
            xy[i + 1] = sin * x + cos * y + offsetY;
        }
        return xy;
    }
}
