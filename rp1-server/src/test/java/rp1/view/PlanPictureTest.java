package rp1.view;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.awt.Color;
import java.awt.Dimension;
import java.awt.image.BufferedImage;
import java.nio.file.Path;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import rp1.rossum.RsPlan;

/** A floor plan drawn into a file, for documentation. */
class PlanPictureTest {

    @Test
    void theContestPlanIsDrawnAtItsPictureSize(@TempDir Path dir) throws Exception {
        Path picture = dir.resolve("contest.png");
        PlanPicture.write(Worlds.floorPlan("contest.txt"), picture);
        BufferedImage image = ImageIO.read(picture.toFile());
        RsPlan plan = rp1.planparser.RsPlanParser.parseFile(Worlds.floorPlan("contest.txt"));
        Dimension size = Pictures.sizeFor(plan.getBounds());
        assertEquals(size.width, image.getWidth());
        assertEquals(size.height, image.getHeight());
        assertEquals(Color.white, new Color(image.getRGB(size.width / 2, 2)), "the margin");
    }
}
