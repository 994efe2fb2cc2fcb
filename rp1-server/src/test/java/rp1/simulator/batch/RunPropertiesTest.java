package rp1.simulator.batch;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** What a run's run.ini keeps of the user's properties. */
class RunPropertiesTest {
    @Test
    void aKeyTheSweepLeavesOutIsRemovedWithItsContinuationLines() {
        String text = "dlcEnabled=true\n  snapshotFileName = end.png\nsnapshotFileName: a\\\n   b.png\nsnapshotInterval=5\n";
        assertEquals("dlcEnabled=true\nsnapshotInterval=5\n\n", RunFolder.withoutKey(text, "snapshotFileName"));
    }

    @Test
    void aKeyThatOnlyBeginsLikeTheOneLeftOutIsKept() {
        assertEquals("snapshotFileNames=x\n", RunFolder.withoutKey("snapshotFileNames=x", "snapshotFileName"));
    }
}
