package rp1.simulator.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.Random;

import org.junit.jupiter.api.Test;

import rp1.rossum.RsBody;
import rp1.rossum.RsBodyCircle;
import rp1.rossum.RsBodyContactSensor;
import rp1.rossum.RsBodyShape;
import rp1.rossum.RsTransform;
import rp1.simulator.noise.RobotNoise;

/**
 * The contact search places robots' outlines in buffers of its own, one per design: robots of one
 * design share one copy of their outlines, and whatever order the search asks for robots in, the
 * outlines it gets for either robot of the last two are exactly those of that robot at the pose asked.
 */
class PlacedOutlinesTest {
    private final OutlineSources sources = new OutlineSources();
    private int joined;

    @Test
    void robotsOfOneDesignShareTheirOutlinesAndOtherDesignsKeepTheirOwn() {
        Robot a = robot(round(0.1));
        Robot b = robot(round(0.1));
        Robot wider = robot(round(0.12));
        assertSame(a.shapes().outlines(), b.shapes().outlines());
        assertSame(a.shapes().contactSensors().outline(0), b.shapes().contactSensors().outline(0));
        assertNotSame(a.shapes().outlines(), wider.shapes().outlines());
        assertNotSame(a.shapes().contactSensors().outline(0), wider.shapes().contactSensors().outline(0));
    }

    @Test
    void eitherOfTheLastTwoRobotsAskedForIsPlacedExactlyWhereAsked() {
        Robot[] robots = {robot(round(0.1)), robot(round(0.1)), robot(box()), robot(round(0.12))};
        // Something to measure every placement against, bit for bit.
        Outlines probe = Outlines.at(robots[2].shapes().outlines(), new RsTransform(0.3, 0.25, 0.1));
        PlacedOutlines placed = new PlacedOutlines();
        Random random = new Random(5);
        RsTransform[] poses = new RsTransform[robots.length];
        Deque<Integer> lastTwo = new ArrayDeque<>();
        Outlines[] got = new Outlines[robots.length];
        for (int i = 0; i < 5_000; i++) {
            int r = random.nextInt(robots.length);
            boolean moved = poses[r] == null || random.nextInt(3) == 0;
            if (moved) {
                poses[r] = new RsTransform(2 * Math.PI * random.nextDouble(), 0.4 * random.nextDouble(),
                        0.4 * random.nextDouble());
            }
            Outlines o = placed.of(robots[r], poses[r]);
            if (!moved && lastTwo.contains(r)) {
                assertSame(got[r], o, "a robot asked for again at the same pose is not placed again");
            }
            got[r] = o;
            lastTwo.remove(r);
            lastTwo.addFirst(r);
            if (lastTwo.size() > 2) {
                lastTwo.removeLast();
            }
            for (int k : lastTwo) {
                Outlines expected = Outlines.at(robots[k].shapes().outlines(), poses[k]);
                assertEquals(Double.doubleToLongBits(expected.distance(probe)), Double.doubleToLongBits(got[k].distance(probe)),
                        "robot " + k + " after asking for robot " + r + " (step " + i + ")");
                assertEquals(expected.overlaps(probe), got[k].overlaps(probe));
            }
        }
    }

    @Test
    void aContactSensorIsPlacedWhereAsked() {
        Robot a = robot(round(0.1));
        PlacedOutlines placed = new PlacedOutlines();
        Outlines probe = Outlines.at(new double[][] {{0.1, -0.1, 0.2, -0.1, 0.2, 0.1, 0.1, 0.1}}, new RsTransform());
        double[][] bumper = a.shapes().contactSensors().outline(0);
        for (double x : new double[] {0.0, 0.005, 0.02, -0.1}) {
            RsTransform pose = new RsTransform(0.0, x, 0.0);
            assertEquals(Double.doubleToLongBits(Outlines.at(bumper, pose).distance(probe)),
                    Double.doubleToLongBits(placed.sensor(bumper, pose).distance(probe)), "at x = " + x);
        }
    }

    private Robot robot(RsBody body) {
        return new Robot(++joined, body, EventSinks.NOWHERE, RobotNoise.NONE, sources);
    }

    /** A round robot of {@code radius} with a bumper at its front, as two are built by two clients. */
    private static RsBody round(double radius) {
        RsBody body = new RsBody("round");
        body.addPart(new RsBodyCircle(0.0, 0.0, radius));
        body.addPart(new RsBodyContactSensor(new double[] {radius - 0.01, -0.05, radius + 0.005, -0.05, radius + 0.005, 0.05,
                radius - 0.01, 0.05}, 4));
        return body;
    }

    private static RsBody box() {
        RsBody body = new RsBody("box");
        body.addPart(new RsBodyShape(new double[] {-0.1, -0.08, 0.12, -0.08, 0.12, 0.08, -0.1, 0.08}, 4));
        return body;
    }
}
