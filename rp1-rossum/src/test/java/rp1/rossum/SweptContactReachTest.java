package rp1.rossum;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.junit.jupiter.api.Test;

/**
 * The swept contact search skips walls that the moving body cannot reach before testing edge pairs.
 * The skip must never change a contact time: for many random bodies, walls and motions, near and far,
 * grazing and crossing, the search with the skip gives exactly what testing every pair gives.
 */
class SweptContactReachTest {
    private static final int CASES = 20_000;

    @Test
    void skippingWallsOutOfReachNeverChangesAStraightMotionsContact() {
        Random random = new Random(7);
        int skipped = 0;
        int hits = 0;
        for (int i = 0; i < CASES; i++) {
            Drive d = Drive.random(random);
            double all = d.everyPair();
            double withSkip = SweptContact.line(d.body, d.body.length, d.wall, d.wall.length, d.dx, d.dy);
            assertEquals(all, withSkip, 0.0, "case " + i);
            skipped += Double.isInfinite(withSkip) ? 1 : 0;
            hits += Double.isInfinite(all) ? 0 : 1;
        }
        assertTrue(skipped > CASES / 10 && hits > CASES / 20, "both outcomes occur: " + skipped + " without contact, " + hits + " with");
    }

    @Test
    void skippingWallsOutOfReachNeverChangesATurnsContact() {
        Random random = new Random(11);
        int hits = 0;
        for (int i = 0; i < CASES; i++) {
            double x = random.nextDouble() * 4 - 2;
            double y = random.nextDouble() * 4 - 2;
            RsSegment[] body = polygon(random, x, y, 0.05 + 0.4 * random.nextDouble());
            RsSegment[] wall = wall(random);
            // Turning on the spot, or about a pivot some way off (an arc).
            double cx = random.nextBoolean() ? x : x + (random.nextDouble() - 0.5) * 3;
            double cy = random.nextBoolean() ? y : y + (random.nextDouble() - 0.5) * 3;
            double angle = (random.nextDouble() - 0.5) * 4 * Math.PI;
            double all = SweptContact.arcSearch(body, body.length, wall, wall.length, cx, cy, angle);
            double withSkip = SweptContact.arc(body, body.length, wall, wall.length, cx, cy, angle);
            assertEquals(all, withSkip, 0.0, "case " + i);
            hits += Double.isInfinite(all) ? 0 : 1;
        }
        assertTrue(hits > CASES / 20 && hits < CASES - CASES / 10, hits + " of " + CASES + " with contact");
    }

    @Test
    void wallsBesideOrBehindTheBandABodySweepsAreTurnedDownWithoutLosingAContact() {
        Random random = new Random(19);
        int turnedDown = 0;
        for (int i = 0; i < CASES; i++) {
            Drive d = Drive.random(random);
            // Drives "for ever" now and then, and bodies as far from the plan's origin as an arena's corner.
            double far = i % 5 == 0 ? 1.0e5 : 1.0;
            double offset = i % 3 == 0 ? 60.0 : 0.0;
            RsSegment[] body = moved(d.body, offset);
            RsSegment[] wall = moved(d.wall, offset);
            if (SweptContact.outOfLineBand(body, body.length, wall, wall.length, d.dx * far, d.dy * far)) {
                turnedDown++;
                assertEquals(Double.POSITIVE_INFINITY, SweptContact.lineSearch(body, body.length, wall, wall.length,
                        d.dx * far, d.dy * far), 0.0, "case " + i + " was turned down");
            }
            // A search of one body against many walls works the body's extents out once: the same answers.
            double[] extents = SweptContact.bodyExtents(body, body.length, d.dx * far, d.dy * far);
            assertEquals(SweptContact.line(body, body.length, wall, wall.length, d.dx * far, d.dy * far),
                    SweptContact.line(body, body.length, wall, wall.length, d.dx * far, d.dy * far, extents), 0.0,
                    "case " + i);
            double found = random.nextDouble();
            assertEquals(SweptContact.lineBeyond(body, body.length, wall, wall.length, d.dx * far, d.dy * far, found),
                    SweptContact.lineBeyond(body, body.length, wall, wall.length, d.dx * far, d.dy * far, found,
                            extents), "case " + i);
        }
        assertTrue(turnedDown > CASES / 5, turnedDown + " of " + CASES + " turned down");
        // A round robot of radius 0.1 m driving along x for ever, beside a pillar whose near side is 0.15 m
        // off its path: turned down, though within the reach of the disc about its first vertex; a
        // pillar across its band is not.
        RsSegment[] robot = polygonOf(BodyOutline.circlePoints(0, 0, 0.1));
        RsSegment[] beside = square(5, 0.15, 0.1);
        assertTrue(SweptContact.outOfLineBand(robot, robot.length, beside, beside.length, 5.0e5, 0));
        assertEquals(Double.POSITIVE_INFINITY, SweptContact.line(robot, robot.length, beside, beside.length, 5.0e5, 0));
        RsSegment[] across = square(5, 0.05, 0.1);
        assertTrue(!SweptContact.outOfLineBand(robot, robot.length, across, across.length, 5.0e5, 0));
        assertTrue(Double.isFinite(SweptContact.line(robot, robot.length, across, across.length, 5.0e5, 0)));
        // Behind the robot, and beyond where a 1 m drive ends.
        RsSegment[] behind = square(-1, -0.05, 0.1);
        assertTrue(SweptContact.outOfLineBand(robot, robot.length, behind, behind.length, 5.0e5, 0));
        assertTrue(SweptContact.outOfLineBand(robot, robot.length, across, across.length, 1.0, 0));
    }

    @Test
    void wallsSkippedAsBeyondAContactFoundHaveNoEarlierContact() {
        Random random = new Random(13);
        int skipped = 0;
        for (int i = 0; i < CASES; i++) {
            Drive d = Drive.random(random);
            double found = random.nextDouble();
            if (SweptContact.lineBeyond(d.body, d.body.length, d.wall, d.wall.length, d.dx, d.dy, found)) {
                skipped++;
                double contact = d.everyPair();
                assertTrue(contact > found, "case " + i + ": skipped a contact at " + contact + " before " + found);
            }
        }
        assertTrue(skipped > CASES / 20, skipped + " of " + CASES + " skipped");
        // A unit square driving 2 m along x meets a wall at x = 3 after half the way, and not beyond it.
        RsSegment[] square = square(0, 0, 1);
        RsSegment[] wall = {new RsSegment(2, -5, 2, 5)};
        assertEquals(0.5, SweptContact.line(square, square.length, wall, wall.length, 2, 0), 0.0);
        assertTrue(!SweptContact.lineBeyond(square, square.length, wall, wall.length, 2, 0, 0.5));
        assertTrue(SweptContact.lineBeyond(square, square.length, wall, wall.length, 2, 0, 0.49));
    }

    @Test
    void aWallTheBodyJustReachesAtTheEndOfItsMotionIsStillFound() {
        // A unit square from (0, 0) driving 2 m along x: its front edge reaches x = 3 exactly at the end.
        RsSegment[] body = square(0, 0, 1);
        RsSegment[] wall = {new RsSegment(3, -5, 3, 5)};
        assertEquals(1.0, SweptContact.line(body, body.length, wall, wall.length, 2, 0), 0.0);
        // Its far corner sweeps a circle of radius sqrt(2) about the origin: a wall touching it is met.
        RsSegment[] tangent = {new RsSegment(Math.sqrt(2.0), -5, Math.sqrt(2.0), 5)};
        double turn = SweptContact.arc(body, body.length, tangent, tangent.length, 0, 0, 2 * Math.PI);
        assertEquals(SweptContact.arcSearch(body, body.length, tangent, tangent.length, 0, 0, 2 * Math.PI), turn, 0.0);
        assertTrue(Double.isFinite(turn));
    }

    @Test
    void passingOverPointsThatGoBesideAnEdgeNeverChangesAStraightMotionsContact() {
        Random random = new Random(17);
        int hits = 0;
        for (int i = 0; i < CASES; i++) {
            Drive d = Drive.random(random);
            // Now and then a drive "for ever" (a robot told to go on at its speed), as far as 500 km.
            double far = i % 5 == 0 ? 1.0e5 : 1.0;
            double expected = plainEveryPair(d.body, d.wall, d.dx * far, d.dy * far);
            assertEquals(expected, SweptContact.lineSearch(d.body, d.body.length, d.wall, d.wall.length, d.dx * far,
                    d.dy * far), 0.0, "case " + i);
            hits += Double.isInfinite(expected) ? 0 : 1;
        }
        assertTrue(hits > CASES / 20, hits + " of " + CASES + " with contact");
        // On the grid: squares driving along an axis past walls whose ends lie exactly on the lines their
        // corners travel, walls along the direction of travel, and corners meeting corners.
        for (int i = 0; i < CASES; i++) {
            double x = random.nextInt(9) - 4;
            double y = random.nextInt(9) - 4;
            RsSegment[] body = square(x, y, 1 + random.nextInt(2));
            double wx = random.nextInt(13) - 6;
            double wy = random.nextInt(13) - 6;
            RsSegment[] wall = {new RsSegment(wx, wy, wx + random.nextInt(5) - 2, wy + random.nextInt(5) - 2)};
            double dx = random.nextBoolean() ? random.nextInt(9) - 4 : 0;
            double dy = dx == 0 ? random.nextInt(9) - 4 : (random.nextBoolean() ? dx : 0);
            assertEquals(plainEveryPair(body, wall, dx, dy), SweptContact.lineSearch(body, body.length, wall, wall.length,
                    dx, dy), 0.0, "grid case " + i);
        }
    }

    /** Every vertex of each against every edge of the other, the intersection computed for each pair. */
    private static double plainEveryPair(RsSegment[] body, RsSegment[] wall, double dx, double dy) {
        RsSegSect sect = new RsSegSect();
        double best = Double.POSITIVE_INFINITY;
        for (RsSegment p : body) {
            for (RsSegment e : wall) {
                if (sect.process(p.x, p.y, dx, dy, e.x, e.y, e.v.x, e.v.y) && sect.t1 < best) {
                    best = sect.t1;
                }
            }
        }
        for (RsSegment p : wall) {
            for (RsSegment e : body) {
                if (sect.process(p.x, p.y, -dx, -dy, e.x, e.y, e.v.x, e.v.y) && sect.t1 < best) {
                    best = sect.t1;
                }
            }
        }
        return best;
    }

    /**
     * A body of 5 to 45 cm anywhere in a 4 m square about the origin driving up to 3 m either way along
     * each axis, and a wall.
     */
    private record Drive(RsSegment[] body, RsSegment[] wall, double dx, double dy) {
        static Drive random(Random random) {
            RsSegment[] body = polygon(random, random.nextDouble() * 4 - 2, random.nextDouble() * 4 - 2,
                    0.05 + 0.4 * random.nextDouble());
            RsSegment[] wall = SweptContactReachTest.wall(random);
            double dx = (random.nextDouble() - 0.5) * 6;
            return new Drive(body, wall, dx, (random.nextDouble() - 0.5) * 6);
        }

        /** The contact found by testing every pair of edges. */
        double everyPair() {
            return SweptContact.lineSearch(body, body.length, wall, wall.length, dx, dy);
        }
    }

    /** A convex polygon of 3 to 8 vertices on a circle of radius r about (x, y), as closed edges. */
    private static RsSegment[] polygon(Random random, double x, double y, double r) {
        int n = 3 + random.nextInt(6);
        double start = random.nextDouble() * 2 * Math.PI;
        double[] px = new double[n];
        double[] py = new double[n];
        for (int i = 0; i < n; i++) {
            double a = start + 2 * Math.PI * i / n;
            px[i] = x + r * Math.cos(a);
            py[i] = y + r * Math.sin(a);
        }
        RsSegment[] edges = new RsSegment[n];
        for (int i = 0; i < n; i++) {
            edges[i] = new RsSegment(px[i], py[i], px[(i + 1) % n], py[(i + 1) % n]);
        }
        return edges;
    }

    /** A wall: a single segment or a small polygon, anywhere in a 6 m square about the origin. */
    private static RsSegment[] wall(Random random) {
        double x = (random.nextDouble() - 0.5) * 6;
        double y = (random.nextDouble() - 0.5) * 6;
        if (random.nextBoolean()) {
            return polygon(random, x, y, 0.05 + random.nextDouble());
        }
        double a = random.nextDouble() * 2 * Math.PI;
        double length = random.nextDouble() * 4;
        return new RsSegment[] {new RsSegment(x, y, x + length * Math.cos(a), y + length * Math.sin(a))};
    }

    /** The closed outline through the points x0, y0, x1, y1, ... */
    private static RsSegment[] polygonOf(double[] p) {
        int n = p.length / 2;
        RsSegment[] edges = new RsSegment[n];
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            edges[i] = new RsSegment(p[2 * i], p[2 * i + 1], p[2 * j], p[2 * j + 1]);
        }
        return edges;
    }

    /** Copies of the edges moved by (offset, offset). */
    private static RsSegment[] moved(RsSegment[] edges, double offset) {
        RsSegment[] out = new RsSegment[edges.length];
        for (int i = 0; i < edges.length; i++) {
            RsSegment e = edges[i];
            out[i] = new RsSegment(e.x + offset, e.y + offset, e.x + e.v.x + offset, e.y + e.v.y + offset);
        }
        return out;
    }

    private static RsSegment[] square(double x, double y, double side) {
        return new RsSegment[] {
            new RsSegment(x, y, x + side, y), new RsSegment(x + side, y, x + side, y + side),
            new RsSegment(x + side, y + side, x, y + side), new RsSegment(x, y + side, x, y)};
    }
}
