package rp1.planparser;

import java.io.IOException;

import rp1.rossum.RsNavNode;
import rp1.rossum.RsObject;
import rp1.rossum.RsPlacement;
import rp1.rossum.RsPlan;
import rp1.rossum.RsTarget;

/**
 * The point-like objects: {@code target} ({@code geometry: x, y, radius;}), {@code placement}
 * ({@code geometry: x, y, orientationDegrees, radius;}) and navigation {@code node}
 * ({@code geometry: x, y;}). Geometry is required; targets and placements also take a
 * {@code lineWidth} in pixels. Lengths are converted to metres, the placement's orientation to radians.
 */
final class PointDeclaration extends Declaration {
    /** What each kind of point takes. */
    private enum Kind {
        TARGET(3, "x, y, radius", "Invalid number of parameters in geometry specification", true),
        PLACEMENT(4, "x, y, orientation in degrees, radius",
                "Invalid number of parameters in numeric specification", true),
        NODE(2, "x, y", "Invalid number of parameters in geometry specification", false);

        final int count;
        final String meaning;
        final String countProblem;
        final boolean hasLineWidth;

        Kind(int count, String meaning, String countProblem, boolean hasLineWidth) {
            this.count = count;
            this.meaning = meaning;
            this.countProblem = countProblem;
            this.hasLineWidth = hasLineWidth;
        }
    }

    private final Kind kind;
    private double[] geometry;

    private PointDeclaration(RsObject object, Kind kind) {
        super(object, false, kind.hasLineWidth ? "geometry, lineWidth" : "geometry");
        this.kind = kind;
    }

    static PointDeclaration target(String name, RsPlan plan) {
        return new PointDeclaration(new RsTarget(name, plan), Kind.TARGET);
    }

    static PointDeclaration placement(String name, RsPlan plan) {
        return new PointDeclaration(new RsPlacement(name, plan), Kind.PLACEMENT);
    }

    static PointDeclaration node(String name, RsPlan plan) {
        return new PointDeclaration(new RsNavNode(name, plan), Kind.NODE);
    }

    @Override
    protected boolean specificItem(Token item, ValueReader in) throws IOException, RsParsingException {
        if (item.text().equals("geometry")) {
            geometry = convert(in.numbers(kind.count, kind.countProblem, kind.meaning), in);
            return true;
        }
        if (item.text().equals("lineWidth") && kind.hasLineWidth) {
            int width = in.integer("Invalid syntax where positive integer value expected").integer();
            if (object instanceof RsTarget) {
                ((RsTarget) object).lineWidth = width;
            } else {
                ((RsPlacement) object).lineWidth = width;
            }
            return true;
        }
        return false;
    }

    /** Lengths to metres; a placement's orientation (third value) from degrees to radians, unnormalized. */
    private double[] convert(NumberList v, ValueReader in) throws RsParsingException {
        double[] g = new double[v.values().length];
        for (int i = 0; i < g.length; i++) {
            g[i] = kind == Kind.PLACEMENT && i == 2 ? v.values()[2] * Math.PI / 180.0 : in.length(v, i);
        }
        return g;
    }

    @Override
    RsObject finish(Token close, PlanLexer lexer) throws RsParsingException {
        if (geometry == null) {
            throw lexer.error(close, "Missing geometry specification: a " + object.getClassName()
                    + " needs geometry: " + kind.meaning + ";");
        }
        object.setGeometry(geometry);
        return object;
    }
}
