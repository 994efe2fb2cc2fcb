package rp1.view;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.List;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import rp1.rossum.RsPlacement;
import rp1.rossum.RsPlan;
import rp1.rossum.RsRectangle;
import rp1.rossum.RsTransform;
import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.event.RsPlacementEvent;
import rp1.rossum.event.RsTimeoutEvent;
import rp1.rossum.request.RsMotionRequest;
import rp1.simulator.scenario.Scenario;
import rp1.simulator.scenario.ScenarioClient;

/** Picture files written by a headless run: at an interval of simulated time, and at exit. */
@Timeout(60)
class SnapshotWriterTest {

    @Test
    void aHeadlessRunWritesAPictureAtEachMultipleOfTheIntervalWhileTheWorldChangesAndOneAtExit(@TempDir Path dir)
            throws Exception {
        Path file = dir.resolve("run.png");
        RsPlan plan;
        try (Scenario s = Scenario.shippedPlan("WhiteRoom.txt")) {
            plan = s.simulation().getWorld().getPlan();
            Worlds.RecordingLog log = new Worlds.RecordingLog();
            RunningView view = ViewLauncher.start(s.simulation(),
                    Worlds.config("snapshotFileName", file.toString(), "snapshotInterval", "0.5"), log, () -> { });
            assertFalse(view.hasWindow(), "tests run headless");
            assertTrue(view.writesPictures());
            ScenarioClient c = s.connect(new ScenarioClient(ClientZero.build()));
            c.once(RsPlacementEvent.class, e -> c.sendMotionRequest(new RsMotionRequest(0.5, 0.0, 1.2)));
            c.once(RsMotionHaltedEvent.class, e -> c.sendTimeoutRequest(1.0));
            c.sendPlacementRequest("home");
            c.await(RsTimeoutEvent.class);
            s.simulation().shutdown();
            view.close();
        }
        assertEquals(List.of("run-0000.000.png", "run-0000.500.png", "run-0001.000.png", "run-0001.500.png", "run.png"),
                names(dir), "the motion ends at 1.2 s; nothing changes after the picture at 1.5 s");
        for (String name : names(dir)) {
            BufferedImage image = ImageIO.read(dir.resolve(name).toFile());
            assertEquals(800, image.getWidth(), name);
            assertEquals(800 + Pictures.CAPTION_BAND, image.getHeight(), name + ": the plan, and the time and scale under it");
        }
        BufferedImage last = ImageIO.read(file.toFile());
        PixelProbe p = new PixelProbe(last, ViewTransform.fit(plan.getBounds(), 800, 800));
        RsPlacement home = plan.getPlacementArray()[0];
        RsTransform end = new RsTransform(home.orientation, home.x + 0.6 * Math.cos(home.orientation),
                home.y + 0.6 * Math.sin(home.orientation));
        assertEquals(Color.blue, p.atBody(end, ClientZero.HEAD_X, 0.0), "the robot where it stopped, 0.6 m from home");
    }

    private static List<String> names(Path dir) throws IOException {
        try (Stream<Path> files = Files.list(dir)) {
            return files.map(f -> f.getFileName().toString()).sorted().collect(Collectors.toList());
        }
    }

    @Test
    void intervalPicturesAreNamedWithTheirTimeBeforeTheExtension() {
        assertEquals(Paths.get("out/run-0012.500.png"), SnapshotWriter.fileAt(Paths.get("out/run.png"), 12.5));
        assertEquals(Paths.get("world-12345.000"), SnapshotWriter.fileAt(Paths.get("world"), 12345.0));
    }

    @Test
    void aPictureIs800PixelsAlongThePlansLongerSide() {
        assertEquals(new java.awt.Dimension(800, 800), Pictures.sizeFor(new RsRectangle(-0.025, -0.025, 3.05, 3.05)));
        assertEquals(new java.awt.Dimension(800, 329), Pictures.sizeFor(new RsRectangle(0, 0, 10, 4)));
        assertEquals(new java.awt.Dimension(329, 800), Pictures.sizeFor(new RsRectangle(0, 0, 4, 10)));
    }

    @Test
    void theScaleBarHasARoundLength() {
        assertEquals(1.0, Pictures.roundLength(1.9));
        assertEquals(2.0, Pictures.roundLength(4.99));
        assertEquals(5.0, Pictures.roundLength(5.0));
        assertEquals(0.5, Pictures.roundLength(0.61), 1e-12);
    }

    @Test
    void aPictureOfARunDrawsEachRobotsPathAndItsTimeUnderThePlan() throws Exception {
        RsPlan plan = rp1.planparser.RsPlanParser.parse("wall s { geometry: 0, 0, 4, 0, 0.02; }\n"
                + "wall n { geometry: 0, 4, 4, 4, 0.02; }\n", "room");
        rp1.simulator.outcome.Trail path = new rp1.simulator.outcome.Trail("r", List.of(new double[] {1.0, 1.0, 3.0, 1.0}));
        BufferedImage image = Pictures.renderCaptioned(new Renderer(plan),
                rp1.simulator.snapshot.WorldSnapshot.planOnly(plan), List.of(path));
        java.awt.Dimension size = Pictures.sizeFor(plan.getBounds());
        ViewTransform view = ViewTransform.fit(plan.getBounds(), size.width, size.height);
        assertTrue(inked(image, view.pixelX(2.0), view.pixelY(1.0)), "the path, where the robot went");
        assertFalse(inked(image, view.pixelX(2.0), view.pixelY(2.0)), "nowhere else");
        boolean text = false;
        for (int x = 0; x < 100 && !text; x++) {
            for (int y = size.height; y < image.getHeight() && !text; y++) {
                text = image.getRGB(x, y) != Color.white.getRGB();
            }
        }
        assertTrue(text, "the simulated time, written under the plan");
    }

    /** Whether a pixel within 2 pixels of (px, py) is not white: lines fall on whole pixels near their place. */
    private static boolean inked(BufferedImage image, double px, double py) {
        for (int dx = -2; dx <= 2; dx++) {
            for (int dy = -2; dy <= 2; dy++) {
                if (image.getRGB((int) Math.round(px) + dx, (int) Math.round(py) + dy) != Color.white.getRGB()) {
                    return true;
                }
            }
        }
        return false;
    }
}
