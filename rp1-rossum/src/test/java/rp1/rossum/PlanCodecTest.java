package rp1.rossum;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.io.ByteArrayOutputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.time.Duration;
import java.util.Arrays;
import java.util.Random;

import org.junit.jupiter.api.Test;

class PlanCodecTest {
    private static final Duration LIMIT = Duration.ofSeconds(5);

    /** A plan with one object of every type, as a parser would build it. */
    static RsPlan everyType() {
        RsPlan plan = new RsPlan("every.txt");
        plan.setCaption("Every type");
        RsWall wall = new RsWall("w", plan);
        wall.setGeometry(new double[] {0, 0, 2, 0, 0.2});
        plan.addObject(wall);
        RsWall obstacle = new RsWall("tri", plan);
        obstacle.setGeometry(new double[] {1, 1, 2, 1, 1.5, 2});
        plan.addObject(obstacle);
        RsTarget target = new RsTarget("goal", plan);
        target.setGeometry(new double[] {0.4, 0.5, 0.25});
        plan.addObject(target);
        RsPlacement home = new RsPlacement("home", plan);
        home.setGeometry(new double[] {2.5, 2.5, Math.toRadians(225), 0.275});
        plan.addObject(home);
        RsNavNode a = node(plan, "a", 1, 2, "A");
        RsNavNode b = node(plan, "b", 3, 4, null);
        b.setLineColor(Color.red);
        RsNavLink link = new RsNavLink("ab", plan);
        link.setNodes(a, b);
        link.setLabel("road");
        link.setColor(Color.yellow);
        plan.addObject(link);
        RsPaint paint = new RsPaint("p", plan);
        paint.setGeometry(new double[] {0, 0, 1, 0, 1, 1, 0, 1});
        paint.setFillColor(Color.black);
        paint.setRegion(7);
        plan.addObject(paint);
        return plan;
    }

    private static RsNavNode node(RsPlan plan, String name, double x, double y, String label) {
        RsNavNode n = new RsNavNode(name, plan);
        n.setGeometry(new double[] {x, y});
        n.setLabel(label);
        plan.addObject(n);
        return n;
    }

    @Test
    void wallTravelsAsItsFourCornersWithoutRepeatingTheFirst() throws IOException {
        RsPlan plan = new RsPlan();
        plan.setCaption("C");
        RsWall wall = new RsWall("w", plan);
        wall.setGeometry(new double[] {0, 0, 2, 0, 0.2});
        plan.addObject(wall);
        Bytes expected = new Bytes().i32(1).str("C").i32(1).i32(RsProtocol.PLAN_WALL).str("w").i32(8)
                .f64(0).f64(-0.1).f64(2).f64(-0.1).f64(2).f64(0.1).f64(0).f64(0.1);
        assertArrayEquals(expected.bytes(), PlanCodec.encode(plan));
    }

    @Test
    void nodeAndLinkTravelWithoutGeometryCountAndLinkByNodeNames() throws IOException {
        RsPlan plan = new RsPlan();
        RsNavNode a = node(plan, "a", 1.5, -2, "A");
        RsNavNode b = node(plan, "b", 3, 4, null);
        RsNavLink link = new RsNavLink("ab", plan);
        link.setNodes(a, b);
        plan.addObject(link);
        Bytes expected = new Bytes().i32(1).str("").i32(3)
                .i32(RsProtocol.PLAN_NAV_NODE).str("a").f64(1.5).f64(-2).str("A").i32(1).i32(0).i32(255).i32(255)
                .i32(RsProtocol.PLAN_NAV_NODE).str("b").f64(3).f64(4).str("").i32(1).i32(0).i32(255).i32(255)
                .i32(RsProtocol.PLAN_NAV_LINK).str("ab").str("a").str("b").str("").i32(1).i32(0).i32(255).i32(255);
        assertArrayEquals(expected.bytes(), PlanCodec.encode(plan));
    }

    @Test
    void paintTravelsClosedWithItsFillColourButNotItsRegion() throws IOException {
        RsPlan plan = new RsPlan();
        RsPaint paint = new RsPaint("p", plan);
        paint.setGeometry(new double[] {0, 0, 1, 0, 0, 1});
        paint.setColor(Color.black);
        paint.setRegion(3);
        plan.addObject(paint);
        Bytes expected = new Bytes().i32(1).str("").i32(1).i32(RsProtocol.PLAN_PAINT).str("p").i32(8)
                .f64(0).f64(0).f64(1).f64(0).f64(0).f64(1).f64(0).f64(0).i32(1).i32(0).i32(0).i32(0);
        assertArrayEquals(expected.bytes(), PlanCodec.encode(plan));
        RsPaint back = (RsPaint) PlanCodec.decode(expected.bytes()).getObjectByName("p");
        assertEquals(0, back.getRegion());
        assertEquals(Color.lightGray, back.lineColor);
        assertEquals(Color.black, back.fillColor);
        assertEquals(3, back.getSegmentArray().length);
    }

    @Test
    void everyObjectSurvivesTheRoundTrip() throws IOException {
        RsPlan sent = everyType();
        RsPlan got = PlanCodec.decode(PlanCodec.encode(sent));
        assertEquals("Every type", got.getCaption());
        assertEquals(sent.getObjectCount(), got.getObjectCount());
        for (int i = 0; i < sent.getObjectCount(); i++) {
            RsObject s = sent.getObjects().get(i);
            RsObject g = got.getObjects().get(i);
            assertSame(s.getClass(), g.getClass(), s.getName());
            assertEquals(s.getName(), g.getName());
            assertArrayEquals(s.getGeometry(), g.getGeometry(), 0.0, s.getName());
        }
        RsNavNode b = (RsNavNode) got.getObjectByName("b");
        assertEquals(Color.red, b.lineColor);
        assertEquals(Color.red, b.fillColor, "node colours arrive as line and fill colour");
        assertEquals("", b.getLabel(), "a null label arrives empty");
        assertEquals("A", ((RsNavNode) got.getObjectByName("a")).getLabel());
        RsNavLink link = (RsNavLink) got.getObjectByName("ab");
        assertSame(got.getObjectByName("a"), link.n0);
        assertSame(b, link.n1);
        assertEquals("road", link.getLabel());
        assertEquals(Color.yellow, link.fillColor);
        assertArrayEquals(new RsNavLink[] {link}, b.link, "the link is recorded at its nodes");
    }

    @Test
    void emptyPlanIsAvailableWithCaptionAndNoObjects() throws IOException {
        RsPlan plan = new RsPlan();
        plan.setCaption("Nothing");
        byte[] bytes = PlanCodec.encode(plan);
        assertArrayEquals(new Bytes().i32(1).str("Nothing").i32(0).bytes(), bytes);
        RsPlan got = PlanCodec.decode(bytes);
        assertEquals("Nothing", got.getCaption());
        assertEquals(0, got.getObjectCount());
    }

    @Test
    void noPlanIsOneZeroAndDecodesToNull() throws IOException {
        assertArrayEquals(new byte[4], PlanCodec.encode(null));
        assertNull(PlanCodec.decode(new byte[4]));
    }

    @Test
    void geometryCountZeroLeavesTheGeometryUnset() throws IOException {
        byte[] bytes = new Bytes().i32(1).str("").i32(1).i32(RsProtocol.PLAN_TARGET).str("t").i32(0).bytes();
        RsObject t = PlanCodec.decode(bytes).getObjectByName("t");
        assertInstanceOf(RsTarget.class, t);
        assertEquals(false, t.isGeometrySet);
    }

    @Test
    void everyTruncationIsAProtocolErrorNamingAField() {
        byte[] whole = PlanCodec.encode(everyType());
        assertTimeoutPreemptively(LIMIT, () -> {
            for (int n = 0; n < whole.length; n++) {
                byte[] part = Arrays.copyOf(whole, n);
                RsProtocolException e = assertThrows(RsProtocolException.class, () -> PlanCodec.decode(part));
                assertTrue(e.getField().startsWith("plan"), e.getMessage());
            }
        });
    }

    @Test
    void truncationInsideANodeLabelNamesThatField() {
        byte[] bytes = new Bytes().i32(1).str("").i32(1).i32(RsProtocol.PLAN_NAV_NODE).str("n").f64(1).f64(2)
                .bytes();
        RsProtocolException e = assertThrows(RsProtocolException.class, () -> PlanCodec.decode(bytes));
        assertEquals("plan object[0] label", e.getField());
    }

    @Test
    void unknownObjectTypeNamesTheIndexAndTheType() {
        byte[] bytes = new Bytes().i32(1).str("").i32(2).i32(RsProtocol.PLAN_TARGET).str("t").i32(0)
                .i32(9).str("x").bytes();
        RsProtocolException e = assertThrows(RsProtocolException.class, () -> PlanCodec.decode(bytes));
        assertEquals("plan object[1] type", e.getField());
        assertTrue(e.getMessage().contains("9"), e.getMessage());
    }

    @Test
    void absurdCountsAreRefusedBeforeAnythingIsAllocated() {
        byte[] objects = new Bytes().i32(1).str("").i32(Integer.MAX_VALUE).bytes();
        assertEquals("plan object count", assertThrows(RsProtocolException.class,
                () -> PlanCodec.decode(objects)).getField());
        byte[] geometry = new Bytes().i32(1).str("").i32(1).i32(RsProtocol.PLAN_WALL).str("w").i32(-1).bytes();
        assertEquals("plan object[0] geometry count", assertThrows(RsProtocolException.class,
                () -> PlanCodec.decode(geometry)).getField());
    }

    @Test
    void linkToANodeNotReceivedBeforeIsAProtocolError() {
        byte[] bytes = new Bytes().i32(1).str("").i32(1).i32(RsProtocol.PLAN_NAV_LINK).str("l").str("a").str("b")
                .str("").i32(0).bytes();
        RsProtocolException e = assertThrows(RsProtocolException.class, () -> PlanCodec.decode(bytes));
        assertEquals("plan object[0] node0", e.getField());
    }

    @Test
    void linkToSomethingThatIsNotANodeIsAProtocolError() {
        byte[] bytes = new Bytes().i32(1).str("").i32(2).i32(RsProtocol.PLAN_TARGET).str("t").i32(0)
                .i32(RsProtocol.PLAN_NAV_LINK).str("l").str("t").str("t").str("").i32(0).bytes();
        RsProtocolException e = assertThrows(RsProtocolException.class, () -> PlanCodec.decode(bytes));
        assertTrue(e.getMessage().contains("not a node"), e.getMessage());
    }

    @Test
    void duplicateNamesAndLeftoverBytesAreProtocolErrors() {
        byte[] twice = new Bytes().i32(1).str("").i32(2).i32(RsProtocol.PLAN_TARGET).str("t").i32(0)
                .i32(RsProtocol.PLAN_TARGET).str("t").i32(0).bytes();
        assertEquals("plan object[1] name", assertThrows(RsProtocolException.class,
                () -> PlanCodec.decode(twice)).getField());
        byte[] extra = new Bytes().i32(0).i32(0).bytes();
        assertThrows(RsProtocolException.class, () -> PlanCodec.decode(extra));
    }

    @Test
    void colourComponentOutOfRangeIsAProtocolError() {
        byte[] bytes = new Bytes().i32(1).str("").i32(1).i32(RsProtocol.PLAN_NAV_NODE).str("n").f64(0).f64(0)
                .str("").i32(1).i32(300).i32(0).i32(0).bytes();
        assertEquals("plan object[0] color red", assertThrows(RsProtocolException.class,
                () -> PlanCodec.decode(bytes)).getField());
    }

    @Test
    void randomCorruptionYieldsAPlanOrAProtocolErrorNeverAnythingElse() {
        byte[] whole = PlanCodec.encode(everyType());
        Random random = new Random(20240601L);
        assertTimeoutPreemptively(LIMIT, () -> {
            for (int i = 0; i < 3000; i++) {
                byte[] bad = whole.clone();
                for (int k = random.nextInt(4); k >= 0; k--) {
                    bad[random.nextInt(bad.length)] = (byte) random.nextInt(256);
                }
                try {
                    PlanCodec.decode(bad);
                } catch (RsProtocolException expected) {
                    // The only acceptable failure.
                }
            }
        });
    }

    /** Expected wire bytes, written independently of WireOut with Java's DataOutputStream. */
    static final class Bytes {
        private final ByteArrayOutputStream buffer = new ByteArrayOutputStream();
        private final DataOutputStream out = new DataOutputStream(buffer);

        Bytes i32(int v) {
            return write(() -> out.writeInt(v));
        }

        Bytes f64(double v) {
            return write(() -> out.writeDouble(v));
        }

        Bytes str(String s) {
            return write(() -> out.writeUTF(s));
        }

        private Bytes write(Write w) {
            try {
                w.run();
            } catch (IOException e) {
                throw new UncheckedIOException("a byte array does not fail", e);
            }
            return this;
        }

        byte[] bytes() {
            return buffer.toByteArray();
        }

        private interface Write {
            void run() throws IOException;
        }
    }
}
