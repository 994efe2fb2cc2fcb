package rp1.simulator.batch;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;

/** What a refused --resume says differs: where two long values part, not two beginnings that are alike. */
class SweepSpecTest {
    private static SweepSpec spec(String seeds) {
        return SweepSpec.of("maxSimulationTime=30\n", Map.of("contest.txt", "caption: \"c\";"),
                SweepOptions.parse(new String[] {"-p", "x.ini", "--seeds", seeds, "--out", "out"}), "1234");
    }

    @Test
    void longSeedListsThatDifferLateAreShownWhereTheyDiffer() {
        assertEquals(List.of("the seeds (--seeds): ...,24,25,26,27,28,29,30 there, ...,24,25,26,27,28,29,31 here"),
                spec("1-30").differences(spec("1-29,31")));
        assertEquals(List.of("the seeds (--seeds): 1 there, 1,2 here"), spec("1").differences(spec("1-2")));
    }
}
