package rp1.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The side-by-side part's reading of both programs' lines and its summary, without running either. */
class SideBySideTest {
    private static final Pattern RP1 = Pattern.compile("([0-9][0-9,]*\\.[0-9]+) simulated s per wall s");
    private static final Pattern PEER = Pattern.compile("loop-only ([0-9.]+)");

    @Test
    void readsTheFiguresBothProgramsPrint() {
        List<String> ours = List.of("warming up", "scale arena   1000 robots, 40.0 m (1000 placed in 0.6 s), simulated 6.0 to"
                + " 36.0 s:        30.24 simulated s per wall s (32.20 per CPU s),    375,843 events/s, heap used 35 MB");
        assertEquals(30.24, SideBySide.parse(ours, RP1).getAsDouble());
        List<String> big = List.of("scale arena      1 robots, 40.0 m (1 placed in 0.1 s), simulated 4000.0 to 24000.0 s:"
                + "   123,456.78 simulated s per wall s (1.00 per CPU s)");
        assertEquals(123456.78, SideBySide.parse(big, RP1).getAsDouble());
        List<String> stage = List.of("stage N=1000 threads=1 sim_per_wall=4.81 (sim 30 s in 6.24 s wall, peak RSS 557.5 MB,"
                + " loop-only 5.46)");
        assertEquals(5.46, SideBySide.parse(stage, PEER).getAsDouble());
        assertTrue(SideBySide.parse(List.of("stage run failed (rc=1)"), PEER).isEmpty());
    }

    @Test
    void summarisesEachCountByItsMediansAndEveryRoundsRatio() {
        List<SideBySide.Peer> peers = List.of(new SideBySide.Peer("Stage 4.3.0 (loop-only)", Path.of("s"), 1000),
                new SideBySide.Peer("ir-sim 2.12.0 (loop-only)", Path.of("i"), 100));
        List<List<SideBySide.Round>> rounds = List.of(List.of(
                new SideBySide.Round(36.3, new double[] {6.34, Double.NaN}),
                new SideBySide.Round(33.3, new double[] {7.00, Double.NaN}),
                new SideBySide.Round(31.5, new double[] {6.40, Double.NaN})));
        String table = SideBySide.table(List.of(1000), peers, rounds);
        assertTrue(table.contains("| 1,000 | 33.3 (36.3, 33.3, 31.5) | 6.40 | — | 5.73, 4.76, 4.92 (4.92) |"), table);
        assertTrue(table.startsWith("| Robots | RP1, median (rounds) | Stage 4.3.0 (loop-only), median |"), table);
    }

    @Test
    void medianLeavesOutRoundsThatGaveNoFigure() {
        assertEquals(2.0, SideBySide.median(new double[] {3.0, Double.NaN, 1.0}));
        assertEquals(2.0, SideBySide.median(new double[] {3.0, 2.0, 1.0}));
        assertTrue(Double.isNaN(SideBySide.median(new double[] {Double.NaN})));
    }

    @Test
    void findsThePeersOnlyWhereStagesScriptIs(@TempDir Path dir) throws Exception {
        assertNull(SideBySide.peersFolder(dir.toString(), null));
        Files.writeString(dir.resolve("stage_bench.sh"), "#!/bin/sh\n");
        assertEquals(dir.toAbsolutePath().normalize(), SideBySide.peersFolder(null, dir.toString()));
        assertEquals(dir.toAbsolutePath().normalize(), SideBySide.peersFolder(dir.toString(), "/nowhere"));
        assertNull(SideBySide.peersFolder(null, ""), "no folder named: none looked for");
        assertNull(SideBySide.peersFolder(null, null), "no folder named: none looked for");
    }
}
