package rp1.planparser;

import java.io.IOException;

import rp1.rossum.RsObject;
import rp1.rossum.RsPlan;
import rp1.rossum.RsWall;

/**
 * {@code wall}: a straight wall given by its centre line and thickness,
 * {@code geometry: x0, y0, x1, y1, thickness;} (required). A centre line shorter than 1e-9 m is
 * ignored, as in the original.
 */
final class WallDeclaration extends Declaration {
    private static final double MIN_SIZE = 1.0e-9;

    private double[] geometry;

    WallDeclaration(String name, RsPlan plan) {
        super(new RsWall(name, plan), true, "geometry, constraint");
    }

    @Override
    protected boolean specificItem(Token item, ValueReader in) throws IOException, RsParsingException {
        switch (item.text()) {
            case "geometry":
                geometry(in);
                return true;
            case "constraint":
                in.identifier("Invalid syntax where object constraint specification expected");
                return true;
            default:
                return false;
        }
    }

    private void geometry(ValueReader in) throws IOException, RsParsingException {
        NumberList list = in.numbers();
        double[] v = list.values();
        if (v.length != 5) {
            throw in.lexer().error(list.end(), "Invalid number of parameters in geometry specification: a wall"
                    + " takes 5 numbers (x0, y0, x1, y1, thickness), found " + v.length);
        }
        double[] g = in.lengths(list);
        if (g[4] <= MIN_SIZE) {
            throw in.lexer().error(list.end(), "Invalid thickness specification for wall: expected a thickness"
                    + " greater than zero, found " + v[4]);
        }
        if (Math.hypot(g[2] - g[0], g[3] - g[1]) > MIN_SIZE) {
            geometry = g;
        }
    }

    @Override
    RsObject finish(Token close, PlanLexer lexer) throws RsParsingException {
        if (geometry != null) {
            object.setGeometry(geometry);
        }
        if (!object.isGeometrySet) {
            throw lexer.error(close, "Missing or invalid geometry specification: a wall needs"
                    + " geometry: x0, y0, x1, y1, thickness; with two distinct end points");
        }
        return object;
    }
}
