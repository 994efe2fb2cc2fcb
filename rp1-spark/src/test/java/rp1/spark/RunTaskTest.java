package rp1.spark;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.StringReader;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Properties;

import org.junit.jupiter.api.Test;

import rp1.simulator.batch.PropertiesText;

/** A run's properties moved from the driver's folders to the executor's. */
class RunTaskTest {
    @Test
    void theOutputFilesMoveToTheExecutorsFolderWhateverCharactersTheDriversPathHas() throws Exception {
        // run.ini escapes its values: rewriting its text missed a path with a colon or an accented letter,
        // and the executor would have written into the driver's folder.
        String driver = "/srv/expé:riences/out/runs/3-contest";
        Map<String, String> written = new LinkedHashMap<>();
        written.put("dlcName", "rp1demo.bumper.Bumper");
        written.put("recordFileName", driver + "/recording.txt");
        written.put("eventLogFileName", driver + "/events.txt");
        written.put("logFileName", driver + "/server.log");
        written.put("floorPlanFileName", "/srv/plans/contest.txt");
        Path here = Path.of("/tmp/rp1-run-3-contest-123");
        Path plan = here.resolve("plan-contest.txt");
        Properties read = new Properties();
        read.load(new StringReader(RunTask.relocated(PropertiesText.of(written), driver, here, plan)));
        assertEquals(here + "/recording.txt", read.getProperty("recordFileName"));
        assertEquals(here + "/events.txt", read.getProperty("eventLogFileName"));
        assertEquals(here + "/server.log", read.getProperty("logFileName"));
        assertEquals(plan.toString(), read.getProperty("floorPlanFileName"));
        assertEquals("rp1demo.bumper.Bumper", read.getProperty("dlcName"));
    }
}
