package rp1.simulator.record;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import rp1.Replay;
import rp1.simulator.world.WorldModel;

/**
 * A recording's floor plan gets the parser's checks like a plan file: one with a coordinate beyond the
 * limit is refused with its place and status 1, never an OutOfMemoryError.
 */
class ReplayOfAnOutOfRangePlanTest {
    @TempDir
    Path dir;

    @Test
    void aRecordingWhosePlanHasAHugeCoordinateIsRefusedNamingWhereInThePlan() throws Exception {
        Path file = dir.resolve("far.rec");
        Files.write(file, String.join("\n",
                "rp1-recording 1",
                "world-model " + WorldModel.VERSION,
                "seed 7",
                "property \"floorPlanFileName\" \"WhiteRoom.txt\"",
                "plan \"WhiteRoom.txt\" 2",
                "|wall a { geometry: 0, 0, 3, 0, 0.05; }",
                "|placement home { geometry: 1e+300, 2.5, 225, 0.275; }",
                "end 0 0.0 events 0 crc 0",
                "").getBytes(StandardCharsets.UTF_8));
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int status = Replay.run(new String[] {file.toString()}, new PrintStream(new ByteArrayOutputStream()),
                new PrintStream(err, true, StandardCharsets.UTF_8));
        assertEquals(1, status);
        assertEquals("rp1.Replay: " + file + ": its floor plan does not parse here: WhiteRoom.txt:2:28: Value out of"
                + " range: 1e+300 meters is beyond the limit of 1000000 m (1000 km) from the origin for any"
                + " coordinate or length of a plan\n", err.toString(StandardCharsets.UTF_8));
    }
}
