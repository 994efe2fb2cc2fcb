package rp1.planparser;

import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import rp1.rossum.RsPlan;

/**
 * Where the test inputs live: the plans we ship, our syntax sampler, and the original RP1 0.60
 * sample plans, which are not part of the repository and are read only when they are beside it
 * (in {@code ../shared/rp1-0.60-floorplans}); a test that needs them is skipped, with the reason,
 * when they are absent.
 */
final class TestPlans {
    /** The sample plans shipped with RP1 0.60, by file name. */
    private static final List<String> ORIGINAL_NAMES =
            List.of("LineTrack.txt", "WhiteRoom.txt", "ackerman.txt", "test.txt", "trinity2001.txt");

    private TestPlans() {
    }

    /** The project root (the build passes it; tests run from there otherwise). */
    static Path root() {
        return Path.of(System.getProperty("rp1.root", System.getProperty("user.dir")));
    }

    private static Path originalsDirectory() {
        return root().resolve("../shared/rp1-0.60-floorplans").normalize();
    }

    /** An original sample plan; the calling test is skipped when the originals are not beside the project. */
    static Path original(String name) {
        Path file = originalsDirectory().resolve(name);
        assumePresent(file);
        return file;
    }

    /** Skips the calling test, with the reason, if {@code file} is absent (only original sample plans may be). */
    static void assumePresent(Path file) {
        assumeTrue(Files.isRegularFile(file), () -> "skipped: " + file + " is absent; the original RP1 0.60 sample"
                + " plans are test inputs kept outside the repository, read only when ../shared/rp1-0.60-floorplans is beside it");
    }

    /** A plan we ship in FloorPlans/. */
    static Path shipped(String name) {
        return root().resolve("FloorPlans").resolve(name);
    }

    /** Our plan written with every construct the original samples use (see SamplerPlanTest). */
    static Path sampler() {
        try {
            return Path.of(TestPlans.class.getResource("/planparser/sampler.txt").toURI());
        } catch (URISyntaxException e) {
            throw new IllegalStateException(e);
        }
    }

    /** The original sample plans, whether or not they are present (see {@link #assumePresent}). */
    static List<Path> originals() {
        return ORIGINAL_NAMES.stream().map(originalsDirectory()::resolve).collect(Collectors.toList());
    }

    static List<Path> shippedPlans() {
        return list(shipped("WhiteRoom.txt").getParent());
    }

    /** Every plan file: ours, the sampler and the original's. */
    static List<Path> all() {
        return Stream.of(shippedPlans().stream(), Stream.of(sampler()), originals().stream())
                .flatMap(s -> s).collect(Collectors.toList());
    }

    static RsPlan parse(Path file) {
        try {
            return RsPlanParser.parseFile(file);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        } catch (RsParsingException e) {
            throw new AssertionError(e.getMessage(), e);
        }
    }

    private static List<Path> list(Path dir) {
        try (Stream<Path> files = Files.list(dir)) {
            return files.filter(p -> p.toString().endsWith(".txt")).sorted().collect(Collectors.toList());
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
