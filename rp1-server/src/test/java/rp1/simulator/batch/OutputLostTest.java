package rp1.simulator.batch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A sweep whose output folder loses its {@code sweep.ini} while it runs (the folder removed, or
 * replaced) stops at the next run and says so, instead of writing the rest of its runs as if they
 * were the whole sweep.
 */
class OutputLostTest {
    @TempDir
    Path dir;

    @Test
    void aSweepWhoseOutputFolderLostItsSpecificationStopsAndSaysSo() throws Exception {
        Path out = dir.resolve("out");
        Path p = HomeSweep.properties(dir, "vandal", VandalDlc.class);
        Files.write(p, List.of("param.delete=" + out.resolve(SweepSpec.FILE)), StandardOpenOption.APPEND);
        InProcessSweep sweeps = new InProcessSweep();
        assertEquals(1, sweeps.run("-p", p.toString(), "--seeds", "1-5", "--jobs", "1", "--out", out.toString()),
                sweeps.out() + sweeps.err());
        assertTrue(sweeps.err().contains(out + " lost its sweep.ini while the sweep ran"), sweeps.err());
        assertTrue(Files.isDirectory(out.resolve("runs/1-home")), "the first run went");
        assertFalse(Files.exists(out.resolve("runs/3-home")), "no run after the loss was noticed went");
    }
}
