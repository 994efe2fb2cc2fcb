package rp1.simulator.batch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;

/** {@code --vary}: lists, decimal ranges, the keys a sweep sets itself, and the product of several. */
class VariedTest {
    @Test
    void aListKeepsItsOrderAndARangeIsCountedInDecimals() {
        assertEquals(List.of("0.5", "0.3"), Varied.parse("param.speed=0.5,0.3,0.5").values());
        assertEquals(List.of("0.1", "0.2", "0.3"), Varied.parse("param.speed=0.1:0.3:0.1").values());
        assertEquals(List.of("10", "25", "40"), Varied.parse("maxSimulationTime=10:40:15").values());
    }

    @Test
    void aRangeWhoseStepsMissItsEndAndTwoSpellingsOfOneNumberAreRefused() {
        // "Both ends included": 1:2:0.3 would have run 1, 1.3, 1.6 and 1.9 without a word about 2.
        assertEquals("--vary x=1:2:0.3: the steps from 1 by 0.3 do not reach 2 (the last below it is 1.9): give a TO"
                + " they reach, both ends being run",
                assertThrows(IllegalArgumentException.class, () -> Varied.parse("x=1:2:0.3")).getMessage());
        assertEquals("--vary param.speed=0.3,0.30,.3: 0.30 is 0.3 again",
                assertThrows(IllegalArgumentException.class, () -> Varied.parse("param.speed=0.3,0.30,.3")).getMessage());
        assertEquals(List.of("a", "A"), Varied.parse("param.name=a,A").values(), "words are not numbers");
    }

    @Test
    void seedsUpToTheLargestAreCountedWithoutOverflow() {
        assertEquals(List.of(Long.MAX_VALUE - 1, Long.MAX_VALUE), SweepOptions.seeds("9223372036854775806-9223372036854775807"));
        assertEquals(List.of(Long.MAX_VALUE), SweepOptions.seeds("9223372036854775807"));
    }

    @Test
    void keysTheSweepSetsItselfAndBadRangesAreRefusedSayingWhy() {
        assertEquals("--vary randomSeed: the sweep sets randomSeed for each run itself; use --seeds",
                assertThrows(IllegalArgumentException.class, () -> Varied.parse("randomSeed=1,2")).getMessage());
        assertEquals("--vary viewPort: the sweep sets viewPort for each run itself",
                assertThrows(IllegalArgumentException.class, () -> Varied.parse("viewPort=8080,8081")).getMessage());
        assertEquals("--vary x=3:1:1: a range needs FROM <= TO and a positive STEP",
                assertThrows(IllegalArgumentException.class, () -> Varied.parse("x=3:1:1")).getMessage());
        assertEquals("--vary x=1:a:1: \"a\" is not a number",
                assertThrows(IllegalArgumentException.class, () -> Varied.parse("x=1:a:1")).getMessage());
        assertThrows(IllegalArgumentException.class, () -> Varied.parse("x=1,,2"));
        assertThrows(IllegalArgumentException.class, () -> SweepOptions.parse(new String[] {"-p", "a.ini", "--seeds", "1",
            "--out", "o", "--vary", "x=1", "--vary", "x=2"}));
    }

    @Test
    void severalKeysMakeTheirFullProductTheFirstVaryingSlowest() {
        List<Map<String, String>> product = Varied.product(List.of(Varied.parse("a=1,2"), Varied.parse("b=x,y,z")));
        assertEquals(6, product.size());
        assertEquals(Map.of("a", "1", "b", "x"), product.get(0));
        assertEquals(Map.of("a", "1", "b", "z"), product.get(2));
        assertEquals(Map.of("a", "2", "b", "x"), product.get(3));
        assertEquals(List.of(Map.of()), Varied.product(List.of()));
    }
}
