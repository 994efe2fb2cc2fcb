package rp1.web;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.openqa.selenium.By;
import org.openqa.selenium.WebElement;
import org.openqa.selenium.interactions.Actions;

import rp1.Replay;
import rp1.rossum.RsLogAdapter;
import rp1.simulator.launch.LaunchOptions;
import rp1.simulator.launch.RunningServer;
import rp1.simulator.record.Recording;
import rp1.simulator.record.RecordingReader;
import rp1.simulator.record.Replayer;
import rp1.simulator.snapshot.RobotSnapshot;
import rp1.simulator.snapshot.WorldSnapshot;

/**
 * The replay page and the live page in a real browser (headless Chromium): the page opens without
 * errors, draws the robot where the model had it, its slider and event buttons move the clock, and
 * the live page follows a running simulation and sends it clicks. Skipped where there is no Chromium.
 */
@Timeout(180)
class BrowserPageTest {
    @TempDir
    static Path dir;
    static Path recording;
    static Browser browser;

    @BeforeAll
    static void recordAndOpen() throws Exception {
        browser = Browser.open();
        recording = Runs.record(dir, 20.0);
        Path page = dir.resolve("run.html");
        assertEquals(0, Replay.run(new String[] {recording.toString(), "--html", page.toString()}, System.out, System.err));
    }

    @BeforeEach
    void openThePage() {
        browser.open(dir.resolve("run.html").toUri().toString());
    }

    @AfterAll
    static void closeBrowser() {
        if (browser != null) {
            browser.close();
        }
    }

    @Test
    void thePageOpensWithoutErrorsAndHoldsTheRun() {
        assertEquals(List.of(), browser.consoleErrors());
        assertTrue(browser.number("return rp1.frames()") > 100, "frames of every modelling step");
        assertEquals(20.0, browser.number("return rp1.end()"), 1e-9);
        assertEquals("Wanderer", browser.js("return rp1.robots()[0].name"));
    }

    @Test
    void atTenSecondsTheRobotIsDrawnWhereTheModelHadIt() throws Exception {
        Recording r = RecordingReader.read(recording);
        Replayer replayer = Replayer.prepare(r, null, new RsLogAdapter() {
            @Override
            public void logIt(String level, String message) {
            }
        });
        replayer.run(10.0);
        RobotSnapshot expected = WorldSnapshot.atRecordedTime(replayer.simulation()).robots().get(0);

        browser.js("rp1.seek(10)");
        @SuppressWarnings("unchecked")
        Map<String, Number> drawn = (Map<String, Number>) browser.js("return rp1.drawnPose(1)");
        assertEquals(expected.x(), drawn.get("x").doubleValue(), 1e-4, "x");
        assertEquals(expected.y(), drawn.get("y").doubleValue(), 1e-4, "y");
        assertEquals(expected.theta(), drawn.get("theta").doubleValue(), 1e-4, "heading");
        assertTrue(Math.hypot(expected.x() - 2.5, expected.y() - 2.5) > 0.3, "by then it has left home");
    }

    @Test
    void thePointerOnARobotShowsItsNameAndPose() {
        browser.js("rp1.seek(10)");
        WebElement canvas = browser.driver().findElement(By.id("canvas"));
        @SuppressWarnings("unchecked")
        List<Number> at = (List<Number>) browser.js("var r = arguments[0].getBoundingClientRect(), q = rp1.drawnPose(1);"
                + " var p = rp1.pixelOf(q.x, q.y); return [p[0] - r.left - r.width / 2, p[1] - r.top - r.height / 2];", canvas);
        new Actions(browser.driver()).moveToElement(canvas, at.get(0).intValue(), at.get(1).intValue()).perform();
        WebElement tip = browser.driver().findElement(By.id("tip"));
        assertTrue(tip.isDisplayed(), "a tip shows");
        String x = String.format(Locale.ROOT, "x = %.4f m", browser.number("return rp1.drawnPose(1).x"));
        assertTrue(tip.getText().startsWith("Wanderer") && tip.getText().contains(x), tip.getText());
        assertTrue(tip.getText().contains("range sensor"), tip.getText());
    }

    @Test
    void theSliderAndTheEventButtonsMoveTheClock() {
        browser.js("rp1.seek(0)");
        WebElement slider = browser.driver().findElement(By.id("slider"));
        browser.js("arguments[0].value = 500; arguments[0].dispatchEvent(new Event('input'));", slider);
        assertEquals(10.0, browser.number("return rp1.time()"), 1e-9, "the middle of the slider is the middle of the run");
        assertTrue(browser.driver().findElement(By.id("clock")).getText().contains("10.000"));

        browser.driver().findElement(By.id("next")).click();
        double next = browser.number("return rp1.time()");
        assertTrue(next > 10.0, "next event after 10 s: " + next);
        String row = browser.driver().findElement(By.cssSelector("#events div.now")).getText();
        assertEquals(next, Double.parseDouble(row.substring(0, row.indexOf(' '))), 1e-9, "the event marked is the one jumped to");

        browser.driver().findElement(By.id("prev")).click();
        assertTrue(browser.number("return rp1.time()") < next, "previous event");

        WebElement third = browser.driver().findElements(By.cssSelector("#events div")).get(2);
        third.click();
        assertEquals(Double.parseDouble(third.getText().substring(0, third.getText().indexOf(' '))),
                browser.number("return rp1.time()"), 1e-9, "a click on an event jumps to it");
        assertEquals(List.of(), browser.consoleErrors());
    }

    @Test
    void theLivePageFollowsTheRunAndAClickInItMovesTheRobot(@TempDir Path live) throws Exception {
        int port = LiveViewTest.freePort();
        Runs.properties(live, 600.0, "simulationSpeed=1", "viewPort=" + port, "dlcName=" + Sitter.class.getName());
        RunningServer server = Runs.start(live, LaunchOptions.defaults());
        try {
            browser.open("http://127.0.0.1:" + port + "/");
            awaitTrue(() -> browser.js("return rp1.drawnPose(1)") != null, "the robot appears");
            double t0 = browser.number("return rp1.time()");
            awaitTrue(() -> browser.number("return rp1.time()") > t0 + 0.5, "the clock follows the run");
            double x0 = browser.number("return rp1.drawnPose(1).x");
            double y0 = browser.number("return rp1.drawnPose(1).y");
            assertEquals(2.5, x0, 1e-9, "at home");

            WebElement canvas = browser.driver().findElement(By.id("canvas"));
            @SuppressWarnings("unchecked")
            List<Number> at = (List<Number>) browser.js("var r = arguments[0].getBoundingClientRect();"
                    + " var p = rp1.pixelOf(1.0, 1.5); return [p[0] - r.left - r.width / 2, p[1] - r.top - r.height / 2];", canvas);
            new Actions(browser.driver()).moveToElement(canvas, at.get(0).intValue(), at.get(1).intValue()).click().perform();
            awaitTrue(() -> Math.hypot(browser.number("return rp1.drawnPose(1).x") - x0,
                    browser.number("return rp1.drawnPose(1).y") - y0) > 0.1, "the click sent the robot forward");
            assertEquals(List.of(), browser.consoleErrors());
        } finally {
            server.stop();
        }
        assertTrue(server.awaitExit(10, TimeUnit.SECONDS).isPresent());
    }

    @Test
    void theSweepIndexSortsByAnyColumnAndLeadsToEachRunsReplay(@TempDir Path sweep) throws Exception {
        SweepIndexTest.sweep(sweep);
        SweepIndex.write(sweep, true);
        browser.open(sweep.resolve(SweepIndex.NAME).toUri().toString());
        browser.driver().findElement(By.xpath("//table[@id='runs']//th[text()='distance']")).click();
        assertEquals("2", browser.js("return rp1index.rows()[0][0]"), "the shorter distance first");
        browser.driver().findElement(By.xpath("//table[@id='runs']//th[text()='distance']")).click();
        assertEquals("1", browser.js("return rp1index.rows()[0][0]"), "then the longer");
        browser.driver().findElement(By.xpath("//table[@id='runs']//th[text()='end_reason']")).click();
        assertEquals("2", browser.js("return rp1index.rows()[0][0]"), "text sorts as text: client failed... first");
        // Seed 1 never collided: its empty first_collision_time is not a collision at 0, and goes last both ways.
        browser.driver().findElement(By.xpath("//table[@id='runs']//th[text()='first_collision_time']")).click();
        assertEquals("2", browser.js("return rp1index.rows()[0][0]"), "the empty field last");
        browser.driver().findElement(By.xpath("//table[@id='runs']//th[text()='first_collision_time']")).click();
        assertEquals("2", browser.js("return rp1index.rows()[0][0]"), "the empty field last the other way too");
        assertEquals(List.of(), browser.consoleErrors());

        browser.driver().findElement(By.linkText("replay")).click();
        awaitTrue(() -> browser.driver().getCurrentUrl().endsWith("runs/1-WhiteRoom/replay.html"), "the run's page opens");
        assertTrue(browser.number("return rp1.frames()") > 100);
        assertEquals(List.of(), browser.consoleErrors());
    }

    @Test
    void theSweepIndexSummaryShowsMeansAndIntervalsFirstAndAllColumnsOnAClick(@TempDir Path sweep) throws Exception {
        // summary.csv has six columns a metric: 65 for the bumper, distance_mean off a 1600-pixel screen.
        SweepIndexTest.sweep(sweep);
        Files.writeString(sweep.resolve("summary.csv"), "plan,robot,runs,failed,distance_n,distance_mean,distance_sd,"
                + "distance_ci95,distance_min,distance_max\nWhiteRoom.txt,Wanderer,2,1,1,2.5,,,2.5,2.5\n");
        SweepIndex.write(sweep, false);
        browser.open(sweep.resolve(SweepIndex.NAME).toUri().toString());
        String brief = browser.driver().findElement(By.id("summary")).getText();
        assertTrue(brief.contains("distance_mean") && brief.contains("distance_ci95"), brief);
        assertFalse(brief.contains("distance_sd") || brief.contains("distance_max"), brief);
        browser.driver().findElement(By.id("all-columns")).click();
        String all = browser.driver().findElement(By.id("summary")).getText();
        assertTrue(all.contains("distance_sd") && all.contains("distance_max") && all.contains("distance_n"), all);
        assertEquals(List.of(), browser.consoleErrors());
    }

    @Test
    void aSweepIndexWithoutReplayPagesLinksToNoneAndSaysHowToWriteOne(@TempDir Path sweep) throws Exception {
        SweepIndexTest.sweep(sweep);
        SweepIndex.write(sweep, false);
        browser.open(sweep.resolve(SweepIndex.NAME).toUri().toString());
        assertEquals(List.of(), browser.driver().findElements(By.linkText("replay")), "no link to a page that is not there");
        assertTrue(browser.driver().findElement(By.id("runs")).getText().contains("recording.txt --html "),
                "the command that writes it");
        assertEquals(List.of(), browser.consoleErrors());
    }

    private static void awaitTrue(BooleanSupplier condition, String what) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() > deadline) {
                throw new AssertionError("not within 20 s: " + what);
            }
            Thread.sleep(50);
        }
    }
}
