package rp1.planparser;

import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

import rp1.rossum.RsPlan;

/**
 * Random edits of real plans (tokens deleted, duplicated or swapped, the text cut short, random
 * characters put in or overwritten) must each give a plan or an {@link RsParsingException} with a
 * sane position, never another exception and never a hang. Seeded, so every run tests the same inputs.
 */
class PlanMutationTest {
    private static final int MUTANTS_PER_PLAN = 400;
    private static final Duration LIMIT_PER_INPUT = Duration.ofSeconds(2);
    /** Rough tokens: strings, words, numbers, white space, or any single character. */
    private static final Pattern PIECE = Pattern.compile("\"[^\"\\r\\n]*\"|[A-Za-z_][A-Za-z0-9_]*|[0-9.]+|\\s+|.",
            Pattern.DOTALL);

    static List<Path> plans() {
        return TestPlans.all();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("plans")
    void mutantsParseOrFailCleanly(Path file) throws IOException {
        TestPlans.assumePresent(file);
        String text = Files.readString(file, StandardCharsets.UTF_8);
        List<String> pieces = pieces(text);
        Random random = new Random(file.getFileName().toString().hashCode());
        for (int i = 0; i < MUTANTS_PER_PLAN; i++) {
            String mutant = mutate(text, pieces, random);
            assertTimeoutPreemptively(LIMIT_PER_INPUT, () -> parseOrFailCleanly(mutant), () -> "hangs on: " + mutant);
        }
    }

    private static void parseOrFailCleanly(String mutant) {
        try {
            RsPlan plan = RsPlanParser.parse(mutant, "mutant.txt");
            assertNotNull(plan);
            assertTrue(plan.getObjectCount() > 0);
        } catch (RsParsingException e) {
            assertTrue(e.getLine() >= 1 && e.getColumn() >= 1, e.getMessage());
            assertTrue(e.getMessage().startsWith("mutant.txt:" + e.getLine() + ":" + e.getColumn() + ": "));
        } catch (RuntimeException | Error e) {
            fail("parser threw " + e + " on:\n" + mutant, e);
        }
    }

    private static List<String> pieces(String text) {
        List<String> pieces = new ArrayList<>();
        Matcher m = PIECE.matcher(text);
        while (m.find()) {
            pieces.add(m.group());
        }
        return pieces;
    }

    private static String mutate(String text, List<String> pieces, Random random) {
        switch (random.nextInt(6)) {
            case 0:
                return editPieces(pieces, random, (list, k) -> list.remove(k));
            case 1:
                return editPieces(pieces, random, (list, k) -> list.add(k, list.get(k)));
            case 2:
                return editPieces(pieces, random, (list, k) -> list.add(k + 1, list.remove(random.nextInt(list.size()))));
            case 3:
                return text.substring(0, random.nextInt(text.length() + 1));
            case 4:
                return overwrite(text, random);
            default:
                int at = random.nextInt(text.length() + 1);
                return text.substring(0, at) + randomCharacter(random) + text.substring(at);
        }
    }

    private interface Edit {
        void apply(List<String> pieces, int index);
    }

    /** Applies one to three edits at random pieces. */
    private static String editPieces(List<String> original, Random random, Edit edit) {
        List<String> list = new ArrayList<>(original);
        for (int n = 1 + random.nextInt(3); n > 0 && list.size() > 1; n--) {
            edit.apply(list, random.nextInt(list.size() - 1));
        }
        return String.join("", list);
    }

    private static String overwrite(String text, Random random) {
        char[] chars = text.toCharArray();
        for (int n = 1 + random.nextInt(4); n > 0 && chars.length > 0; n--) {
            chars[random.nextInt(chars.length)] = randomCharacter(random);
        }
        return new String(chars);
    }

    /** Mostly the characters that matter to the lexer, sometimes any byte value or a lone CR. */
    private static char randomCharacter(Random random) {
        String interesting = "{}:;,-+./*\"\\\r\n0123456789xXeE.";
        return random.nextBoolean() ? interesting.charAt(random.nextInt(interesting.length()))
                : (char) random.nextInt(256);
    }
}
