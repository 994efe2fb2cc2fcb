package rp1.view;

import java.awt.AWTException;
import java.awt.Color;
import java.awt.Point;
import java.awt.Rectangle;
import java.awt.Robot;
import java.awt.event.InputEvent;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import javax.imageio.ImageIO;
import javax.swing.JMenu;
import javax.swing.JMenuBar;
import javax.swing.JMenuItem;
import javax.swing.SwingUtilities;

import rp1.rossum.RsPlacement;
import rp1.rossum.RsTransform;
import rp1.rossum.event.RsMouseClickEvent;
import rp1.rossum.event.RsPlacementEvent;
import rp1.simulator.SimulationSettings;
import rp1.simulator.scenario.Scenario;
import rp1.simulator.scenario.ScenarioClient;

/**
 * Run on a real display (Xvfb in CI): opens the simulator's window on the WhiteRoom with ClientZero
 * at home, takes a screenshot and checks it shows the world, checks that the status line's clock
 * runs while nothing moves, clicks on the floor with the primary and the secondary button, and
 * checks that the subscribed client is told the floor points; then File → Exit must run the
 * server's exit callback.
 */
public final class WindowCheck {
    private static final long WAIT_MILLIS = 10_000;

    private final Path outputDir;
    private final Robot robot;
    private RunningView view;

    private WindowCheck(Path outputDir) throws AWTException {
        this.outputDir = outputDir;
        this.robot = new Robot();
        robot.setAutoDelay(20);
    }

    /** @param args the directory for the screenshot */
    public static void main(String[] args) {
        ChildCheck.run("WINDOW CHECK", () -> {
            new WindowCheck(Paths.get(args[0])).check();
            return null;
        });
    }

    private void check() throws Exception {
        SimulationSettings paced = SimulationSettings.paced(0.05, 1.0, false, 1L);
        try (Scenario s = Scenario.with(Worlds.whiteRoomText(), paced)) {
            Worlds.RecordingLog log = new Worlds.RecordingLog();
            CountDownLatch exited = new CountDownLatch(1);
            view = ViewLauncher.start(s.simulation(), Worlds.config(), log, exited::countDown);
            if (!view.hasWindow()) {
                throw new AssertionError("no window on DISPLAY=" + System.getenv("DISPLAY") + ": " + log.lines());
            }
            ScenarioClient c = s.connect(new ScenarioClient(ClientZero.build()));
            c.sendPlacementRequest("home");
            c.await(RsPlacementEvent.class);
            awaitRobotShown();
            screenshotShowsTheWorld(s.simulation().getWorld().getPlan().getPlacementArray()[0]);
            statusClockRunsWhileNothingMoves();
            clickReachesTheClient(c, 1.0, 0.6, InputEvent.BUTTON1_DOWN_MASK, MouseButtons.PRIMARY);
            clickReachesTheClient(c, 2.0, 2.7, InputEvent.BUTTON3_DOWN_MASK, MouseButtons.SECONDARY);
            exitRunsTheCallback(exited);
            view.close();
        }
    }

    private void awaitRobotShown() throws Exception {
        long deadline = System.currentTimeMillis() + WAIT_MILLIS;
        while (onEventThread(() -> view.window().canvas().shown().placedRobots().isEmpty())) {
            if (System.currentTimeMillis() > deadline) {
                throw new AssertionError("the window never showed the placed robot");
            }
            Thread.sleep(50);
        }
        robot.waitForIdle();
        Thread.sleep(300);
    }

    private void screenshotShowsTheWorld(RsPlacement home) throws Exception {
        Rectangle frame = onEventThread(() -> view.window().frame().getBounds());
        BufferedImage shot = robot.createScreenCapture(frame);
        Files.createDirectories(outputDir);
        ImageIO.write(shot, "png", outputDir.resolve("window.png").toFile());
        expectColour(shot, frame, 1.5, 0.0, Color.lightGray, "the south wall");
        RsTransform pose = new RsTransform(home.orientation, home.x, home.y);
        var head = pose.map(ClientZero.HEAD_X, 0.0);
        expectColour(shot, frame, head.x, head.y, Color.blue, "ClientZero's head, at home");
        String status = onEventThread(() -> view.window().status().stateText());
        if (!status.contains("ClientZero: x 2.500 m, y 2.500 m, heading 225.0 deg")) {
            throw new AssertionError("status line: " + status);
        }
    }

    private void statusClockRunsWhileNothingMoves() throws Exception {
        double before = statusTime();
        Thread.sleep(1000);
        double after = statusTime();
        if (after - before < 0.5) {
            throw new AssertionError("a second at speed 1 moved the status line's clock from " + before + " to "
                    + after + " s");
        }
    }

    private double statusTime() throws Exception {
        String status = onEventThread(() -> view.window().status().stateText());
        Matcher m = Pattern.compile("^t = (\\d+\\.\\d+) s").matcher(status);
        if (!m.find()) {
            throw new AssertionError("no time in the status line: " + status);
        }
        return Double.parseDouble(m.group(1));
    }

    private void expectColour(BufferedImage shot, Rectangle frame, double x, double y, Color c, String what)
            throws Exception {
        Point p = screenPoint(x, y);
        Color found = new Color(shot.getRGB(p.x - frame.x, p.y - frame.y));
        if (!found.equals(c)) {
            throw new AssertionError(what + " at screen " + p + ": expected " + c + ", found " + found);
        }
    }

    /** The screen pixel where floor point (x, y) is drawn. */
    private Point screenPoint(double x, double y) throws Exception {
        return onEventThread(() -> {
            PlanCanvas canvas = view.window().canvas();
            ViewTransform v = canvas.view();
            Point origin = canvas.getLocationOnScreen();
            return new Point(origin.x + (int) Math.round(v.pixelX(x)), origin.y + (int) Math.round(v.pixelY(y)));
        });
    }

    private void clickReachesTheClient(ScenarioClient c, double x, double y, int buttonMask, int expectedButton)
            throws Exception {
        int before = c.events(RsMouseClickEvent.class).size();
        Point p = screenPoint(x, y);
        robot.mouseMove(p.x, p.y);
        robot.mousePress(buttonMask);
        robot.mouseRelease(buttonMask);
        RsMouseClickEvent e = c.await(RsMouseClickEvent.class, m -> c.events(RsMouseClickEvent.class).indexOf(m) == before);
        double pixel = 1.0 / onEventThread(() -> view.window().canvas().view().getScale());
        if (e.button != expectedButton || e.clickCount != 1 || Math.abs(e.x - x) > pixel || Math.abs(e.y - y) > pixel) {
            throw new AssertionError("clicked " + x + ", " + y + " (one pixel is " + pixel + " m) with button code "
                    + expectedButton + "; the client got " + ScenarioClient.describe(e) + " count " + e.clickCount);
        }
        System.out.println("click at " + x + ", " + y + " -> " + ScenarioClient.describe(e));
    }

    private void exitRunsTheCallback(CountDownLatch exited) throws Exception {
        onEventThread(() -> {
            JMenuBar bar = view.window().frame().getJMenuBar();
            for (int i = 0; i < bar.getMenuCount(); i++) {
                JMenu menu = bar.getMenu(i);
                for (int j = 0; j < menu.getItemCount(); j++) {
                    JMenuItem item = menu.getItem(j);
                    if (item != null && "Exit".equals(item.getText())) {
                        item.doClick();
                    }
                }
            }
            return null;
        });
        if (!exited.await(WAIT_MILLIS, TimeUnit.MILLISECONDS)) {
            throw new AssertionError("File -> Exit did not run the exit callback");
        }
    }

    private interface EventThreadCall<T> {
        T call() throws Exception;
    }

    private static <T> T onEventThread(EventThreadCall<T> call) throws Exception {
        AtomicReference<T> result = new AtomicReference<>();
        AtomicReference<Exception> failure = new AtomicReference<>();
        SwingUtilities.invokeAndWait(() -> {
            try {
                result.set(call.call());
            } catch (Exception e) {
                failure.set(e);
            }
        });
        if (failure.get() != null) {
            throw failure.get();
        }
        return result.get();
    }
}
