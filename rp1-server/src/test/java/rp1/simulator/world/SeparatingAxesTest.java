package rp1.simulator.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.junit.jupiter.api.Test;

import rp1.rossum.RsBody;
import rp1.rossum.RsBodyShape;
import rp1.rossum.RsTransform;
import rp1.simulator.noise.RobotNoise;

/**
 * The contact search's shortcuts for robots pressed together answer only where {@link Outlines} gives
 * the same answer, whatever the robots' shapes, poses and gaps (down to where rounding decides), so
 * that every contact, and every transcript, stays what it was; and they do answer for most pairs.
 */
class SeparatingAxesTest {
    private final OutlineSources sources = new OutlineSources();
    private int joined;

    @Test
    void aHullHoldsItsPolygonAndTheClimbFindsTheFarthestVertexFromAnyStart() {
        Random random = new Random(3);
        for (int round = 0; round < 300; round++) {
            int n = 1 + random.nextInt(12);
            double[] polygon = new double[2 * n];
            for (int k = 0; k < polygon.length; k++) {
                // A coarse grid, so that some points repeat and some lie in line.
                polygon[k] = random.nextInt(7) * 0.05 - 0.15;
            }
            Hull hull = Hull.of(polygon);
            assertTrue(hull.size() >= 1 && hull.size() <= n, "a hull of at most the polygon's vertices");
            for (int k = 0; k < hull.size() && hull.hasEdges(); k++) {
                for (int v = 0; v < n; v++) {
                    double outward = (polygon[2 * v] - hull.x(k)) * hull.normalX(k) + (polygon[2 * v + 1] - hull.y(k)) * hull.normalY(k);
                    assertTrue(outward <= 1e-12, "vertex " + v + " beyond hull edge " + k + " in round " + round);
                }
            }
            for (int k = 0; k < hull.size(); k++) {
                int v = hull.vertex(k);
                assertEquals(polygon[2 * v], hull.x(k));
                assertEquals(polygon[2 * v + 1], hull.y(k));
            }
            for (int d = 0; d < 20; d++) {
                double angle = 2 * Math.PI * random.nextDouble();
                double dx = Math.cos(angle);
                double dy = Math.sin(angle);
                double farthest = Double.NEGATIVE_INFINITY;
                for (int v = 0; v < n; v++) {
                    farthest = Math.max(farthest, polygon[2 * v] * dx + polygon[2 * v + 1] * dy);
                }
                for (int from = 0; from < hull.size(); from++) {
                    assertEquals(farthest, hull.along(hull.farthest(dx, dy, from), dx, dy), 1e-15, "from vertex " + from);
                }
                assertEquals(farthest, hull.along(hull.farthest(dx, dy), dx, dy), 1e-15, "from the octant's start");
                int octant = (int) (angle / (Math.PI / 4));
                if (Math.abs(angle - (octant + 0.5) * Math.PI / 4) < 0.49 * Math.PI / 4) {
                    assertEquals(octant, Hull.octant(dx, dy), "the octant of " + angle);
                }
            }
        }
    }

    @Test
    void whatTheShortcutsSayOutlinesSayAndTheySayItForMostPairsPressedTogether() {
        RsBody[] bodies = {OutlinesTest.roundRobot(), OutlinesTest.boxRobot(), ell(), OutlinesTest.roundRobot()};
        Robot[] robots = new Robot[bodies.length];
        for (int i = 0; i < bodies.length; i++) {
            robots[i] = robot(bodies[i]);
        }
        SeparatingAxes axes = new SeparatingAxes();
        Random random = new Random(17);
        int apartByMuch = 0;
        int shownApart = 0;
        int overlapping = 0;
        int shownCrossing = 0;
        int shownNear = 0;
        int measuredExactly = 0;
        int sensorsBeyond = 0;
        int sensorsTouching = 0;
        for (int i = 0; i < 40_000; i++) {
            Robot a = robots[random.nextInt(robots.length)];
            Robot b = robots[random.nextInt(robots.length)];
            if (a == b) {
                continue;
            }
            // Far from the origin at times, where rounding is coarsest.
            double size = random.nextBoolean() ? 40.0 : 1000.0;
            RsTransform pa = new RsTransform(angle(random), size * random.nextDouble(), size * random.nextDouble());
            double heading = angle(random);
            RsTransform pb = new RsTransform(angle(random), pa.m13 + 0.4 * Math.cos(heading), pa.m23 + 0.4 * Math.sin(heading));
            // Bring b towards a until the gap between them is what was drawn: from touching by a
            // centimetre to apart by one, down to where rounding decides.
            double wanted = Math.signum(random.nextDouble() - 0.3) * Math.pow(10, -2 - 7 * random.nextDouble());
            pb = closedTo(a, pa, b, pb, heading, wanted);
            Outlines oa = Outlines.at(a.shapes().outlines(), pa);
            Outlines ob = Outlines.at(b.shapes().outlines(), pb);
            boolean overlaps = oa.overlaps(ob);
            double distance = oa.distance(ob);
            int found = axes.look(a, pa, b, pb);
            if (found == SeparatingAxes.APART) {
                shownApart++;
                assertFalse(overlaps, "shown apart, yet overlapping: pair " + i + " at a gap of " + wanted);
                if (axes.near(pa, pb, RobotContacts.SAMPLE_SPACING)) {
                    shownNear++;
                    assertEquals(RobotContacts.SAMPLE_SPACING, oa.within(ob, RobotContacts.SAMPLE_SPACING),
                            "shown near: pair " + i);
                }
                double measured = axes.distance(pa, pb);
                if (!Double.isNaN(measured)) {
                    measuredExactly++;
                    assertEquals(Double.doubleToLongBits(distance), Double.doubleToLongBits(measured),
                            "distance of pair " + i + ": " + distance + ", measured " + measured);
                }
            } else if (found == SeparatingAxes.TOUCHING) {
                shownCrossing++;
                assertTrue(overlaps, "shown crossing, yet apart: pair " + i + " at a gap of " + wanted);
            }
            RobotShapes.ContactSensors sensors = a.shapes().contactSensors();
            for (int k = 0; k < sensors.count(); k++) {
                // A contact sensor against the other robot, as the search asks which sensors touch it.
                double limit = 1e-3 + (random.nextBoolean() ? 0.0 : 0.01 * random.nextDouble());
                double expected = Outlines.at(sensors.outline(k), pa).distance(ob, limit);
                int sensed = axes.lookBeyond(sensors.sensor(k), sensors.hulls(k), sensors.outline(k),
                        a.shapes().reach(), pa, b, pb, limit);
                if (sensed == SeparatingAxes.APART) {
                    sensorsBeyond++;
                    assertTrue(expected > limit, "a sensor shown beyond " + limit + ", pair " + i + ": " + expected);
                } else if (sensed == SeparatingAxes.TOUCHING) {
                    sensorsTouching++;
                    assertEquals(0.0, expected, "a sensor shown touching, pair " + i);
                }
            }
            if (overlaps) {
                overlapping++;
            } else if (distance > 2e-5) {
                apartByMuch++;
            }
        }
        assertTrue(overlapping > 5_000 && apartByMuch > 5_000, "both cases are tried: " + overlapping + ", " + apartByMuch);
        assertTrue(shownApart > 0.7 * apartByMuch, "most pairs apart by 20 micrometres or more are shown apart: "
                + shownApart + " of " + apartByMuch);
        assertTrue(shownNear > 0.5 * shownApart, "and most of them near: " + shownNear + " of " + shownApart);
        // The L is not convex: pairs with it are left to Outlines.
        assertTrue(measuredExactly > 0.5 * shownApart, "their distance measured: " + measuredExactly + " of "
                + shownApart);
        assertTrue(sensorsBeyond > 3_000 && sensorsTouching > 400, "sensors shown beyond their limit: "
                + sensorsBeyond + ", touching: " + sensorsTouching);
        assertTrue(shownCrossing > 0.5 * overlapping, "most overlapping pairs are shown crossing: " + shownCrossing
                + " of " + overlapping);
    }

    @Test
    void edgesAlmostInLineFarFromTheOriginAreNeverShownApartWhileOutlinesSayTheyTouch() {
        // Two boxes side by side, their facing edges nearly parallel, a hair apart, where an edge test's
        // rounding is at its worst: whatever the shortcut says, Outlines must agree.
        Robot a = robot(OutlinesTest.boxRobot());
        Robot b = robot(OutlinesTest.boxRobot());
        SeparatingAxes axes = new SeparatingAxes();
        Random random = new Random(23);
        int shown = 0;
        int touching = 0;
        for (int i = 0; i < 20_000; i++) {
            double x = 1000.0 * random.nextDouble();
            double y = 1000.0 * random.nextDouble();
            // A quarter of them edge to edge, touching to the last bit or nearly.
            boolean flush = i % 4 == 0;
            double turn = flush ? 0.0 : (random.nextDouble() - 0.5) * 1e-6;
            double gap = flush ? 0.0 : Math.pow(10, -4 - 10 * random.nextDouble());
            RsTransform pa = new RsTransform(0.0, x, y);
            RsTransform pb = new RsTransform(turn, x + (random.nextDouble() - 0.5) * 0.3, y + 0.16 + gap);
            boolean overlaps = Outlines.at(a.shapes().outlines(), pa).overlaps(Outlines.at(b.shapes().outlines(), pb));
            touching += overlaps ? 1 : 0;
            int found = axes.look(a, pa, b, pb);
            assertFalse(found == SeparatingAxes.TOUCHING && !overlaps, "shown touching, yet apart: pair " + i);
            if (found == SeparatingAxes.APART) {
                shown++;
                assertFalse(overlaps, "pair " + i + ", a gap of " + gap);
            }
        }
        assertTrue(touching > 4_000, "pairs touching are tried: " + touching);
        // A tenth of the gaps drawn are wider than the margin at a kilometre from the origin (7 micrometres).
        assertTrue(shown > 1_000, "pairs apart by more than the margin are shown apart: " + shown);
    }

    /** b moved along the line from a's origin towards it until its outlines are {@code gap} from a's (negative: into a). */
    private static RsTransform closedTo(Robot a, RsTransform pa, Robot b, RsTransform pb, double heading, double gap) {
        Outlines oa = Outlines.at(a.shapes().outlines(), pa);
        double near = 0.0;
        double far = 0.4;
        // Bisect the distance between the origins for the first contact, then step back by the gap.
        for (int k = 0; k < 60; k++) {
            double mid = 0.5 * (near + far);
            RsTransform p = new RsTransform(pb);
            p.m13 = pa.m13 + mid * Math.cos(heading);
            p.m23 = pa.m23 + mid * Math.sin(heading);
            if (oa.overlaps(Outlines.at(b.shapes().outlines(), p))) {
                near = mid;
            } else {
                far = mid;
            }
        }
        RsTransform p = new RsTransform(pb);
        p.m13 = pa.m13 + (far + gap) * Math.cos(heading);
        p.m23 = pa.m23 + (far + gap) * Math.sin(heading);
        return p;
    }

    private static double angle(Random random) {
        return 2 * Math.PI * random.nextDouble();
    }

    private Robot robot(RsBody body) {
        return new Robot(++joined, body, EventSinks.NOWHERE, RobotNoise.NONE, sources);
    }

    /** An L: a polygon that is not convex, whose hull holds room that is not the robot's. */
    private static RsBody ell() {
        RsBody body = new RsBody("ell");
        body.addPart(new RsBodyShape(new double[] {-0.1, -0.1, 0.1, -0.1, 0.1, -0.02, -0.02, -0.02, -0.02, 0.1, -0.1, 0.1},
                6));
        return body;
    }
}
