/**
 * Floor-plan text to {@link rp1.rossum.RsPlan}: the language of behavior.md section 1 and
 * docs/floorplans.md. {@link rp1.planparser.RsPlanParser} is the entry point; a malformed plan gives
 * one {@link rp1.planparser.RsParsingException} naming file, line and column.
 *
 * <p>The path of the data: {@code CharSource} (characters, line endings folded to LF, positions) →
 * {@code PlanLexer} and {@code NumberLexer} (tokens) → {@code PlanParser} (statements, names, units,
 * caption) → one {@code Declaration} per object body ({@code WallDeclaration},
 * {@code PolygonDeclaration} for obstacles and paint, {@code PointDeclaration} for targets,
 * placements and nodes, {@code LinkDeclaration}), which read values through {@code ValueReader}.
 *
 * <p>Plans the original accepted parse to the same objects, quirks included (the token after
 * {@code units}/{@code caption} is not checked, stray tokens in target, placement, node and link
 * bodies are skipped, repeated specifications override, synthesized names keep the original's
 * byte-mask rule). Where the original crashed or hung the plan is rejected with a message instead;
 * in addition, non-simple obstacle and paint polygons and plans without objects are rejected, and
 * {@code kilometers} is accepted as units.
 *
 * <p>Maps: a map_server YAML file ({@code MapFilePlan}, read by {@code MapYaml}) or a {@code bitmap}
 * declaration ({@code BitmapDeclaration}) names an image, which {@code MapSource} finds beside the file
 * and {@code MapImageReader} (PNG through javax.imageio) or {@code PgmReader} turns into an
 * {@code OccupancyGrid}; its occupied cells, merged into rectangles, become walls ({@code MapWalls}).
 */
package rp1.planparser;
