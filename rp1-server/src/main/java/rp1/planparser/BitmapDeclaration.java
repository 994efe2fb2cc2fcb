package rp1.planparser;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;

import rp1.rossum.RsObject;
import rp1.rossum.RsPlan;
import rp1.rossum.RsWall;

/**
 * {@code bitmap}: walls from an occupancy-grid image, on which the rest of the plan (targets,
 * placements, paint, a navigation network) is written in the usual language. Either
 * {@code map: "FILE.yaml";} (a map_server file, see {@link MapYaml}) or {@code image: "FILE";} with
 * {@code resolution: LENGTH;} and optionally {@code origin: x, y[, degrees];},
 * {@code occupiedThresh}, {@code freeThresh} and {@code negate: 0|1;}. Lengths are in the plan's
 * current units, the origin's angle in degrees like every angle of a plan. The colour items colour
 * every wall; the walls are named after the declaration, {@code NAME_1}, {@code NAME_2}, ...
 */
final class BitmapDeclaration extends Declaration {
    private final RsPlan plan;
    private Token imageItem;
    private String image;
    private Token mapItem;
    private String mapFile;
    private Double resolution;
    private double originX;
    private double originY;
    private double yaw;
    private double occupiedThresh = MapSpec.DEFAULT_OCCUPIED;
    private Double freeThresh;
    private Token freeItem;
    private boolean negate;

    BitmapDeclaration(String name, RsPlan plan) {
        super(new RsWall(name, plan), true, "map, image, resolution, origin, occupiedThresh, freeThresh, negate");
        this.plan = plan;
        object.setColor(MapWalls.DEFAULT_COLOR);
    }

    @Override
    String keyword() {
        return "bitmap";
    }

    @Override
    protected boolean specificItem(Token item, ValueReader in) throws IOException, RsParsingException {
        switch (item.text()) {
            case "map":
                mapFile = in.string();
                mapItem = item;
                return true;
            case "image":
                image = in.string();
                imageItem = item;
                return true;
            case "resolution":
                resolution(in);
                return true;
            case "origin":
                origin(in);
                return true;
            case "occupiedThresh":
                occupiedThresh = fraction(in);
                return true;
            case "freeThresh":
                freeThresh = fraction(in);
                freeItem = item;
                return true;
            case "negate":
                Token t = in.integer("Invalid syntax where negate expected (0 or 1)");
                if (t.integer() > 1) {
                    throw in.lexer().error(t, "negate must be 0 or 1, found " + t.text());
                }
                negate = t.integer() == 1;
                return true;
            default:
                return false;
        }
    }

    private void resolution(ValueReader in) throws IOException, RsParsingException {
        NumberList list = in.numbers(1, "Invalid number of parameters in resolution specification",
                "the length of one pixel's side");
        double r = in.length(list, 0);
        if (!(r > 0)) {
            throw in.lexer().error(list.tokens()[0], "Resolution must be above zero, found " + list.tokens()[0].text());
        }
        resolution = r;
    }

    private void origin(ValueReader in) throws IOException, RsParsingException {
        NumberList list = in.numbers();
        int n = list.values().length;
        if (n != 2 && n != 3) {
            throw in.lexer().error(list.end(), "Invalid number of parameters in origin specification: expected 2 or"
                    + " 3 (x, y of the image's lower-left corner, and its rotation in degrees), found " + n);
        }
        originX = in.length(list, 0);
        originY = in.length(list, 1);
        yaw = n == 3 ? Math.toRadians(list.values()[2]) : 0.0;
    }

    private static double fraction(ValueReader in) throws IOException, RsParsingException {
        NumberList list = in.numbers(1, "Invalid number of parameters in threshold specification", "0 to 1");
        double t = list.values()[0];
        if (t > 1) {
            throw in.lexer().error(list.tokens()[0], "A threshold must be between 0 and 1, found " + list.tokens()[0].text());
        }
        return t;
    }

    @Override
    RsObject finish(Token close, PlanLexer lexer) {
        throw new IllegalStateException("a bitmap declares many walls: see objects()");
    }

    @Override
    List<RsObject> objects(Token close, PlanLexer lexer) throws RsParsingException {
        String location = plan.getFileName() == null ? "" : plan.getFileName();
        MapSpec spec;
        Token at;
        if (mapItem != null) {
            if (imageItem != null || resolution != null) {
                throw lexer.error(mapItem, "A bitmap takes either map (a map file) or image and resolution, not both");
            }
            location = MapSource.resolve(location, mapFile);
            spec = mapFileSpec(location, lexer);
            at = mapItem;
        } else {
            spec = imageSpec(close, lexer);
            at = imageItem;
        }
        String where = MapSource.resolve(location, spec.image());
        OccupancyGrid grid;
        try {
            grid = MapSource.read(where, spec);
        } catch (IOException e) {
            throw lexer.error(at, "Cannot read the map image " + where + ": " + e.getMessage());
        }
        String beyond = MapWalls.outOfRange(grid, spec);
        if (beyond != null) {
            throw lexer.error(close, "Object out of range: bitmap " + object.getName() + ": " + beyond);
        }
        return new ArrayList<>(MapWalls.of(grid, spec, plan, object.getName(), object.fillColor, object.lineColor));
    }

    private MapSpec mapFileSpec(String location, PlanLexer lexer) throws RsParsingException {
        String text;
        try {
            text = MapSource.text(location, ParserLimits.MAX_MAP_FILE);
        } catch (IOException e) {
            throw lexer.error(mapItem, "Cannot read the map file " + location + ": " + e.getMessage());
        }
        return MapYaml.parse(text, location).spec();
    }

    private MapSpec imageSpec(Token close, PlanLexer lexer) throws RsParsingException {
        if (image == null || resolution == null) {
            throw lexer.error(close, "Missing " + (image == null ? "image" : "resolution") + " specification: a"
                    + " bitmap needs image: \"FILE\"; and resolution: LENGTH; (or map: \"FILE.yaml\";)");
        }
        double free = freeThresh != null ? freeThresh : Math.min(MapSpec.DEFAULT_FREE, occupiedThresh);
        if (free > occupiedThresh) {
            throw lexer.error(freeItem, "freeThresh " + freeThresh + " is above occupiedThresh " + occupiedThresh
                    + ": a pixel cannot be both free and occupied");
        }
        return new MapSpec(image, resolution, originX, originY, yaw, occupiedThresh, free, negate);
    }
}
