package rp1.planparser;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.lang.reflect.Array;
import java.lang.reflect.Field;
import java.lang.reflect.Modifier;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;

import org.junit.jupiter.api.Test;

import rp1.rossum.RsNavLink;
import rp1.rossum.RsNavNode;
import rp1.rossum.RsPlan;
import rp1.rossum.RsTarget;
import rp1.rossum.RsUnits;
import rp1.rossum.RsWall;
import rp1.rossum.request.RsTargetSelectionRequest;

/**
 * A copied plan is the parsed plan again (every field of every object equal to the bit, walked by
 * reflection so that a field added later and left out of the copy fails here) and shares nothing a run
 * changes; the sweep's {@link ParsedPlans} hands out such copies, parsing each text once.
 */
class PlanCopyTest {
    @Test
    void everyPlanWeHaveCopiesToTheBitAndSharesNothingMutable() {
        List<Path> plans = new ArrayList<>(TestPlans.shippedPlans());
        plans.add(TestPlans.shipped("rooms.yaml"));
        plans.add(TestPlans.sampler());
        for (Path original : TestPlans.originals()) {
            if (Files.isRegularFile(original)) {
                plans.add(original);
            }
        }
        for (Path file : plans) {
            RsPlan parsed = TestPlans.parse(file);
            RsPlan copy = parsed.copy();
            assertTrue(parsed.getObjectCount() > 0, file + " has objects");
            new Walk(parsed, copy, file.toString()).compare(parsed, copy, "plan");
        }
    }

    @Test
    void aCopysTargetSelectionAndRandomSourceAreItsOwn() {
        RsPlan parsed = TestPlans.parse(TestPlans.shipped("contest.txt"));
        RsPlan copy = parsed.copy();
        copy.setRandom(new Random(7));
        copy.processTargetSelectionRequest(1.0, new RsTargetSelectionRequest(false, null, false, true));
        assertTrue(copy.getTargetArray().length > 0);
        for (RsTarget t : copy.getTargetArray()) {
            assertFalse(t.getSelected(), t.getName() + " deselected in the copy");
        }
        for (RsTarget t : parsed.getTargetArray()) {
            assertTrue(t.getSelected(), t.getName() + " still selected in the parsed plan");
        }
    }

    @Test
    void theNavigationNetworkJoinsTheCopiedNodes() {
        RsPlan copy = TestPlans.parse(TestPlans.shipped("contest.txt")).copy();
        RsNavLink[] links = copy.getNavLinkArray();
        assertTrue(links.length > 0);
        for (RsNavLink link : links) {
            assertSame(copy.getObjectByName(link.n0.getName()), link.n0);
            assertSame(copy.getObjectByName(link.n1.getName()), link.n1);
        }
        for (RsNavNode node : copy.getNavNodeArray()) {
            for (RsNavLink link : node.link) {
                assertSame(copy.getObjectByName(link.getName()), link);
            }
        }
    }

    @Test
    void aPlanHoldingAnObjectOfAnotherClassIsNotCopied() {
        RsPlan plan = new RsPlan("own.txt");
        plan.addObject(new RsWall("w", plan) {
        });
        IllegalStateException e = assertThrows(IllegalStateException.class, plan::copy);
        assertTrue(e.getMessage().contains("(w)"), e.getMessage());
    }

    @Test
    void parsedPlansGiveEqualCopiesAndParseAgainWhenTheTextChanges() throws Exception {
        String text = Files.readString(TestPlans.shipped("contest.txt"), StandardCharsets.UTF_8);
        ParsedPlans plans = new ParsedPlans();
        RsPlan first = plans.copyOf(text, "contest.txt");
        RsPlan second = plans.copyOf(text, "contest.txt");
        assertNotSame(first, second);
        new Walk(first, second, "contest.txt").compare(first, second, "plan");
        RsPlan changed = plans.copyOf(text.replace("caption: \"", "caption: \"changed\"; // \""), "contest.txt");
        assertEquals("changed", changed.getCaption());
        assertEquals(first.getCaption(), plans.copyOf(text, "contest.txt").getCaption());
    }

    @Test
    void aMalformedPlanIsReportedByEveryRunThatNamesIt() throws IOException {
        ParsedPlans plans = new ParsedPlans();
        for (int run = 0; run < 2; run++) {
            RsParsingException e = assertThrows(RsParsingException.class, () -> plans.copyOf("wall w {\n geometry: 1.0, 2.0;\n}\n", "bad.txt"));
            assertTrue(e.getMessage().startsWith("bad.txt"), e.getMessage());
        }
    }

    /**
     * Walks a plan and its copy side by side: numbers equal to the bit, strings and colours equal,
     * every other object of the client library a different one in the copy (units excepted, which are
     * constants), each object's plan the plan it is in.
     */
    private static final class Walk {
        private final RsPlan original;
        private final RsPlan copy;
        private final String file;
        private final Map<Object, Object> seen = new IdentityHashMap<>();

        Walk(RsPlan original, RsPlan copy, String file) {
            this.original = original;
            this.copy = copy;
            this.file = file;
        }

        void compare(Object a, Object b, String path) {
            if (a == null || b == null) {
                assertSame(a, b, file + ": " + path);
                return;
            }
            assertSame(a.getClass(), b.getClass(), file + ": " + path);
            Class<?> type = a.getClass();
            if (a instanceof String || a instanceof java.awt.Color || a instanceof Number || a instanceof Boolean
                    || a instanceof Character) {
                assertEquals(a, b, file + ": " + path);
                return;
            }
            if (a == original) {
                assertSame(copy, b, file + ": " + path + " is the copy's plan");
                if (!path.equals("plan")) {
                    return;
                }
            } else if (a instanceof RsUnits || a instanceof Random || a instanceof Map) {
                return;
            } else {
                assertNotSame(a, b, file + ": " + path + " is shared");
            }
            if (seen.put(a, b) != null) {
                assertSame(seen.get(a), b, file + ": " + path);
                return;
            }
            if (type.isArray()) {
                assertEquals(Array.getLength(a), Array.getLength(b), file + ": " + path + ".length");
                for (int i = 0; i < Array.getLength(a); i++) {
                    compareValue(type.getComponentType(), Array.get(a, i), Array.get(b, i), path + "[" + i + "]");
                }
                return;
            }
            if (a instanceof List<?> la) {
                List<?> lb = (List<?>) b;
                assertEquals(la.size(), lb.size(), file + ": " + path + ".size");
                for (int i = 0; i < la.size(); i++) {
                    compare(la.get(i), lb.get(i), path + "[" + i + "]");
                }
                return;
            }
            assertTrue(type.getName().startsWith("rp1.rossum."), file + ": " + path + " is a " + type.getName());
            for (Class<?> c = type; c != Object.class; c = c.getSuperclass()) {
                for (Field f : c.getDeclaredFields()) {
                    if (Modifier.isStatic(f.getModifiers())) {
                        continue;
                    }
                    f.setAccessible(true);
                    try {
                        compareValue(f.getType(), f.get(a), f.get(b), path + "." + f.getName());
                    } catch (IllegalAccessException e) {
                        throw new AssertionError(e);
                    }
                }
            }
        }

        private void compareValue(Class<?> type, Object a, Object b, String path) {
            if (type == double.class) {
                assertEquals(Double.doubleToRawLongBits((Double) a), Double.doubleToRawLongBits((Double) b), file + ": " + path);
            } else if (type.isPrimitive()) {
                assertEquals(a, b, file + ": " + path);
            } else {
                compare(a, b, path);
            }
        }
    }

    @Test
    void theWalkNoticesADifferenceAndASharedPart() {
        RsPlan parsed = TestPlans.parse(TestPlans.shipped("contest.txt"));
        RsPlan copy = parsed.copy();
        copy.getTargetArray()[0].radius += 1e-12;
        assertThrows(AssertionError.class, () -> new Walk(parsed, copy, "contest.txt").compare(parsed, copy, "plan"));
        RsPlan again = parsed.copy();
        again.getWallArray()[0].getPolygon().segment[0] = parsed.getWallArray()[0].getPolygon().segment[0];
        assertThrows(AssertionError.class, () -> new Walk(parsed, again, "contest.txt").compare(parsed, again, "plan"));
    }
}
