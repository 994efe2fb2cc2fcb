package rp1.planparser;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.Reader;
import java.io.StringReader;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import rp1.rossum.RsPlan;

/**
 * Reads a floor-plan file (behavior.md section 1, docs/floorplans.md) into an {@link RsPlan}:
 * walls, obstacles, targets, placements, floor paint and the navigation network, in declaration
 * order, in metres and radians, with the caption, the units the file was written in and the file
 * name. A plan that is malformed in any way is rejected as a whole with one {@link RsParsingException}
 * giving the file, line and column of the first error; there is never a partial plan.
 *
 * <p>A file whose name ends in {@code .yaml} or {@code .yml} is an occupancy-grid map in ROS
 * map_server's form instead: its image's occupied pixels become the plan's walls (docs/floorplans.md,
 * "Plans from maps"). Plan text can take walls from such a map too, with a {@code bitmap} declaration.
 *
 * <p>Files are decoded as UTF-8 (bytes that are not UTF-8 become U+FFFD, which like every character
 * above 127 is white space outside strings). LF, CR LF and a lone CR all end a line.
 */
public final class RsPlanParser {
    private RsPlanParser() {
    }

    /**
     * Parses the plan read from {@code in}.
     *
     * @param fileName the name error messages and the plan give the source
     * @throws RsParsingException if the plan is malformed
     * @throws IOException if {@code in} fails
     */
    public static RsPlan parse(Reader in, String fileName) throws IOException, RsParsingException {
        if (MapFilePlan.isMapFile(fileName)) {
            return MapFilePlan.parse(mapText(in, fileName), fileName);
        }
        PlanLexer lexer = new PlanLexer(new CharSource(in), fileName);
        return new PlanParser(lexer, fileName).parse();
    }

    private static String mapText(Reader in, String fileName) throws IOException, RsParsingException {
        char[] text = new char[ParserLimits.MAX_MAP_FILE + 1];
        int n = 0;
        for (int r = 0; r >= 0 && n < text.length; r = in.read(text, n, text.length - n)) {
            n += r;
        }
        if (n > ParserLimits.MAX_MAP_FILE) {
            throw new RsParsingException(fileName, 1, 1, "Map file too long: a map file (image, resolution, origin,"
                    + " thresholds) is at most " + ParserLimits.MAX_MAP_FILE + " characters");
        }
        return new String(text, 0, n);
    }

    /**
     * Parses a plan held in a string.
     *
     * @throws RsParsingException if the plan is malformed
     */
    public static RsPlan parse(String text, String fileName) throws RsParsingException {
        try {
            return parse(new StringReader(text), fileName);
        } catch (IOException e) {
            throw new UncheckedIOException("a StringReader does not fail", e);
        }
    }

    /**
     * Parses the plan file {@code file}, decoded as UTF-8; errors name the file as {@code file} reads.
     *
     * @throws RsParsingException if the plan is malformed
     * @throws IOException if the file cannot be read
     */
    public static RsPlan parseFile(Path file) throws IOException, RsParsingException {
        try (Reader in = new BufferedReader(
                new InputStreamReader(Files.newInputStream(file), StandardCharsets.UTF_8))) {
            return parse(in, file.toString());
        }
    }
}
