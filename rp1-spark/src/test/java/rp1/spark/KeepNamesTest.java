package rp1.spark;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.Set;

import org.junit.jupiter.api.Test;

/** A --keep name that no run left a file of is told at the sweep's end: a mistyped name brings nothing back. */
class KeepNamesTest {
    @Test
    void namesNoRunLeftAreTheOnesTold() {
        Set<String> left = Set.of("events.txt", "recording.txt", "run.ini");
        assertEquals(List.of("evnts.txt"), SparkRuns.notLeft(Set.of("evnts.txt", "recording.txt"), left));
        assertEquals(List.of(), SparkRuns.notLeft(Set.of("all", "events.txt"), left), "all is every file");
        assertEquals(List.of(), SparkRuns.notLeft(Set.of(), left));
    }
}
