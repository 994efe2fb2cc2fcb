package rp1.planparser;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Objects;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

import rp1.rossum.PlanCodec;
import rp1.rossum.RsNavLink;
import rp1.rossum.RsNavNode;
import rp1.rossum.RsObject;
import rp1.rossum.RsPaint;
import rp1.rossum.RsPlan;

/**
 * Every plan, parsed and sent through the plan-event encoding, reaches the client with the same
 * objects: type, name, geometry, and the labels and colours the protocol carries.
 */
class PlanRoundTripTest {
    private static final double EPS = 1e-12;

    static List<Path> plans() {
        return TestPlans.all();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("plans")
    void clientReceivesTheSameObjects(Path file) throws IOException {
        TestPlans.assumePresent(file);
        RsPlan sent = TestPlans.parse(file);
        RsPlan got = PlanCodec.decode(PlanCodec.encode(sent));
        assertEquals(Objects.toString(sent.getCaption(), ""), got.getCaption());
        assertEquals(sent.getObjectCount(), got.getObjectCount());
        for (int i = 0; i < sent.getObjectCount(); i++) {
            assertSameObject(sent.getObjects().get(i), got.getObjects().get(i));
        }
    }

    private static void assertSameObject(RsObject s, RsObject g) {
        String name = s.getName();
        assertSame(s.getClass(), g.getClass(), name);
        assertEquals(name, g.getName());
        assertArrayEquals(s.getGeometry(), g.getGeometry(), EPS, name);
        if (s instanceof RsNavNode || s instanceof RsNavLink) {
            assertEquals(Objects.toString(s.label, ""), g.label, name);
            assertEquals(s.lineColor, g.lineColor, name);
            assertEquals(s.lineColor, g.fillColor, name);
        }
        if (s instanceof RsNavLink) {
            assertEquals(((RsNavLink) s).n0.getName(), ((RsNavLink) g).n0.getName(), name);
            assertEquals(((RsNavLink) s).n1.getName(), ((RsNavLink) g).n1.getName(), name);
        }
        if (s instanceof RsNavNode) {
            assertEquals(((RsNavNode) s).link.length, ((RsNavNode) g).link.length, name);
        }
        if (s instanceof RsPaint) {
            assertEquals(s.fillColor, g.fillColor, name);
        }
    }
}
