package rp1.planparser;

import java.io.IOException;
import java.util.List;
import java.util.Locale;

import rp1.rossum.RsPlan;
import rp1.rossum.RsWall;

/**
 * A plan read from a map_server YAML file rather than plan text: the map's walls and nothing else,
 * named {@code map_1}, {@code map_2}, ... (a plan that also needs targets or placements declares
 * {@code bitmap { map: "FILE.yaml"; }} in plan text instead).
 */
final class MapFilePlan {
    private MapFilePlan() {
    }

    /** Whether {@code fileName} names a map file ({@code .yaml} or {@code .yml}) rather than plan text. */
    static boolean isMapFile(String fileName) {
        String lower = fileName == null ? "" : fileName.toLowerCase(Locale.ROOT);
        return lower.endsWith(".yaml") || lower.endsWith(".yml");
    }

    /**
     * The plan of the map file whose text is {@code text}, read from {@code fileName} (its image is
     * looked for relative to it).
     *
     * @throws RsParsingException if the file, or its image, is malformed, or the map has no wall
     */
    static RsPlan parse(String text, String fileName) throws RsParsingException {
        MapYaml yaml = MapYaml.parse(text, fileName);
        MapSpec spec = yaml.spec();
        String where = MapSource.resolve(fileName, spec.image());
        OccupancyGrid grid;
        try {
            grid = MapSource.read(where, spec);
        } catch (IOException e) {
            throw yaml.error(yaml.at("image"), "Cannot read the map image " + where + ": " + e.getMessage());
        }
        String beyond = MapWalls.outOfRange(grid, spec);
        if (beyond != null) {
            throw yaml.error(yaml.at("origin"), "Map out of range: " + beyond);
        }
        RsPlan plan = new RsPlan(fileName);
        List<RsWall> walls = MapWalls.of(grid, spec, plan, "map", MapWalls.DEFAULT_COLOR, MapWalls.DEFAULT_COLOR);
        if (walls.isEmpty()) {
            throw yaml.error(yaml.at("image"), "Empty floor plan: no pixel of " + where + " is occupied (darker than"
                    + " occupied_thresh " + spec.occupiedThresh() + (spec.negate() ? ", negated" : "") + ")");
        }
        if (walls.size() > ParserLimits.MAX_OBJECTS) {
            throw yaml.error(yaml.at("image"), "Too many objects: the map's walls number " + walls.size()
                    + ", and a plan may have at most " + ParserLimits.MAX_OBJECTS);
        }
        walls.forEach(plan::addObject);
        return plan;
    }
}
