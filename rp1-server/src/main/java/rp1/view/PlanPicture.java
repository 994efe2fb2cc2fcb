package rp1.view;

import java.io.IOException;
import java.nio.file.Path;
import java.nio.file.Paths;

import rp1.planparser.RsParsingException;
import rp1.planparser.RsPlanParser;
import rp1.rossum.RsPlan;
import rp1.simulator.snapshot.WorldSnapshot;

/**
 * Draws a floor plan into a PNG file, without a display: {@code java -cp ... rp1.view.PlanPicture
 * FloorPlans/WhiteRoom.txt WhiteRoom.png} (for documentation, or to check a plan one is writing).
 */
public final class PlanPicture {
    private PlanPicture() {
    }

    /**
     * @param args the floor-plan file and the picture file; exit status 2 for wrong arguments, 1 if
     *             the plan cannot be read or the picture written
     */
    public static void main(String[] args) {
        if (args.length != 2) {
            System.err.println("usage: rp1.view.PlanPicture PLAN_FILE PICTURE.png");
            System.exit(2);
        }
        try {
            write(Paths.get(args[0]), Paths.get(args[1]));
        } catch (IOException | RsParsingException e) {
            System.err.println(e.getMessage());
            System.exit(1);
        }
    }

    /** Writes the picture of the plan in {@code planFile} to {@code picture}. */
    public static void write(Path planFile, Path picture) throws IOException, RsParsingException {
        RsPlan plan = RsPlanParser.parseFile(planFile);
        Pictures.writePng(Pictures.render(new Renderer(plan), WorldSnapshot.planOnly(plan)), picture);
    }
}
