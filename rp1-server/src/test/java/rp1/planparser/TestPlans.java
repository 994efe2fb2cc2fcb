package rp1.planparser;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import rp1.rossum.RsPlan;

/** Where the test inputs live: our shipped plans and the original's samples beside the project. */
final class TestPlans {
    private TestPlans() {
    }

    /** The project root (the build passes it; tests run from there otherwise). */
    static Path root() {
        return Path.of(System.getProperty("rp1.root", System.getProperty("user.dir")));
    }

    /** The original RP1 0.60 sample plans (test inputs only, never shipped). */
    static Path original(String name) {
        return root().resolve("../shared/rp1-0.60-floorplans").resolve(name).normalize();
    }

    /** A plan we ship in FloorPlans/. */
    static Path shipped(String name) {
        return root().resolve("FloorPlans").resolve(name);
    }

    static List<Path> originals() {
        return list(original("WhiteRoom.txt").getParent());
    }

    static List<Path> shippedPlans() {
        return list(shipped("WhiteRoom.txt").getParent());
    }

    /** Every plan file, ours and the original's. */
    static List<Path> all() {
        return Stream.concat(shippedPlans().stream(), originals().stream()).collect(Collectors.toList());
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
