package rp1.simulator.config;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.util.List;

import org.junit.jupiter.api.Test;

/** "did you mean ...?" for a slip of the keys, and nothing for a word that is no slip. */
class SuggestionTest {
    private static final String USAGE = String.join("\n",
            "usage: rp1 sweep -p PROPERTIES --seeds SEEDS --out DIR [--vary KEY=VALUES ...]",
            "  -cp PATH       where the robot's classes are (also --classpath); wall-clock seconds, 1-16");

    @Test
    void theOptionsAreReadOffTheUsageOnceEachInOrder() {
        assertEquals(List.of("-p", "--seeds", "--out", "--vary", "-cp", "--classpath"), Suggestion.optionsIn(USAGE));
    }

    @Test
    void aSlipOfTheKeysGetsTheOptionItMissed() {
        List<String> options = Suggestion.optionsIn(USAGE);
        assertEquals("--seeds", Suggestion.nearest("--sed", options));
        assertEquals("--seeds", Suggestion.nearest("--Seeds", options), "letter case is a slip too");
        assertEquals("--classpath", Suggestion.nearest("--clas-path", options));
        assertEquals("; did you mean --vary?", Suggestion.didYouMean("--vray", options));
    }

    @Test
    void aWordThatIsNoSlipGetsNothing() {
        List<String> options = Suggestion.optionsIn(USAGE);
        assertNull(Suggestion.nearest("-x", options), "too short to tell a slip from a guess");
        assertNull(Suggestion.nearest("--pictures", options));
        assertNull(Suggestion.nearest("--seeds", options), "a word that is a candidate is no slip");
        assertEquals("", Suggestion.didYouMean("--verbose", options));
        assertEquals("sweep", Suggestion.nearest("swep", List.of("sweep", "replay", "cluster")));
    }
}
