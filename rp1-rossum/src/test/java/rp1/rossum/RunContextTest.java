package rp1.rossum;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** What a client learns of its run: from the server that loads it, from a sweep's environment, or nothing. */
class RunContextTest {
    @TempDir
    Path dir;

    @Test
    void aClientGivenItsRunReadsItsParametersAndSeedAndReportsItsResults() {
        List<String> reported = new ArrayList<>();
        RsClient c = new RsClient();
        c.setRunContext(new RsRunContext() {
            @Override
            public String getParameter(String name) {
                return name.equals("speed") ? "0.3" : null;
            }

            @Override
            public long getSeed() {
                return 42;
            }

            @Override
            public void reportResult(String name, double value) {
                reported.add(name + "=" + value);
            }
        });
        assertEquals("0.3", c.getRunParameter("speed"));
        assertNull(c.getRunParameter("turn"));
        assertEquals(42, c.getRunSeed());
        c.reportRunResult("reached", 1.0);
        assertEquals(List.of("reached=1.0"), reported);
    }

    @Test
    void aSweepsEnvironmentGivesParametersSeedAndAResultsFileWhoseLastLinesWin() throws Exception {
        Path results = dir.resolve("results.txt");
        RsClient c = new RsClient();
        c.setRunContext(RsRunContext.fromEnvironment(Map.of("RP1_SEED", "7", "RP1_PARAM_max_speed", "0.5",
                "RP1_RESULTS", results.toString())));
        assertEquals("0.5", c.getRunParameter("max.speed"));
        assertEquals(7, c.getRunSeed());
        c.reportRunResult("score", 2.5);
        c.reportRunResult("score", 3.0);
        assertEquals(List.of("score 2.5", "score 3.0"), Files.readAllLines(results));
    }

    @Test
    void withoutARunThereAreNoParametersSeedZeroAndResultsGoNowhere() {
        RsClient c = new RsClient();
        c.setRunContext(RsRunContext.fromEnvironment(Map.of()));
        assertNull(c.getRunParameter("speed"));
        assertEquals(0, c.getRunSeed());
        c.reportRunResult("score", 1.0);
    }

    @Test
    void badResultsAreRefusedNamingTheArgument() {
        RsClient c = new RsClient();
        c.setRunContext(RsRunContext.fromEnvironment(Map.of()));
        assertEquals("reportRunResult: name must be letters, digits, _, . or -, got \"two words\"",
                assertThrows(IllegalArgumentException.class, () -> c.reportRunResult("two words", 1)).getMessage());
        assertEquals("reportRunResult: value of score must be finite, got NaN",
                assertThrows(IllegalArgumentException.class, () -> c.reportRunResult("score", Double.NaN)).getMessage());
    }
}
