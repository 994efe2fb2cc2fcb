package rp1.simulator.scenario;

/** Floor plans for scenario tests, small enough to check numbers by hand. */
final class Plans {
    private Plans() {
    }

    /**
     * A 10 m x 4 m room (walls 2 cm thick centred on its edges, so the inner faces are at x = 0.01
     * and x = 9.99, y = 0.01 and y = 3.99) with placements "west" at (1, 2) facing east, "east" at
     * (9, 2) facing west, and "centre" at (5, 2) facing east.
     */
    static final String HALL = String.join("\n",
        "caption: \"hall\";",
        "wall south { geometry: 0, 0, 10, 0, 0.02; }",
        "wall north { geometry: 0, 4, 10, 4, 0.02; }",
        "wall westWall { geometry: 0, 0, 0, 4, 0.02; }",
        "wall eastWall { geometry: 10, 0, 10, 4, 0.02; }",
        "placement west { geometry: 1, 2, 0, 0.1; }",
        "placement east { geometry: 9, 2, 180, 0.1; }",
        "placement centre { geometry: 5, 2, 0, 0.1; }",
        "");

    /** The hall with a 1 cm thick wall "thin" across it at x = 5 (faces at 4.995 and 5.005). */
    static final String HALL_WITH_THIN_WALL = HALL + "wall thin { geometry: 5, 0, 5, 4, 0.01; }\n";

    /** The hall with a 2 cm thick wall "block" across it at {@code x} (faces at x - 0.01 and x + 0.01). */
    static String hallWithBlockAt(double x) {
        return HALL + "wall block { geometry: " + x + ", 0, " + x + ", 4, 0.02; }\n";
    }

    /** The hall with a placement "slant" at (0.5, 2) heading 70 degrees: its back faces the west wall obliquely. */
    static final String HALL_WITH_SLANT = HALL + "placement slant { geometry: 0.5, 2, 70, 0.1; }\n";
}
