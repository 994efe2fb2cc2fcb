package rp1.planparser;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Each file in {@code planparser/errors/} is a malformed plan whose first line reads
 * {@code // expect LINE:COLUMN: MESSAGE}; parsing it must fail at exactly that position with exactly
 * that message (after the file name).
 */
class GoldenErrorFilesTest {
    private static final Pattern EXPECT = Pattern.compile("// expect (\\d+):(\\d+): (.+)");

    static List<Path> errorFiles() throws IOException, URISyntaxException {
        Path dir = Path.of(GoldenErrorFilesTest.class.getResource("/planparser/errors").toURI());
        try (Stream<Path> files = Files.list(dir)) {
            return files.sorted().collect(Collectors.toList());
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("errorFiles")
    void failsWhereAndHowTheFileSays(Path file) throws IOException {
        String firstLine = Files.readAllLines(file, StandardCharsets.UTF_8).get(0);
        Matcher m = EXPECT.matcher(firstLine);
        assertTrue(m.matches(), file.getFileName() + " must start with // expect LINE:COLUMN: MESSAGE");
        RsParsingException e = assertThrows(RsParsingException.class, () -> RsPlanParser.parseFile(file));
        String where = m.group(1) + ":" + m.group(2);
        assertEquals(where + ": " + m.group(3), e.getLine() + ":" + e.getColumn() + ": " + e.getReason(), e.getMessage());
        assertTrue(e.getMessage().startsWith(file + ":" + where + ": "), e.getMessage());
    }
}
