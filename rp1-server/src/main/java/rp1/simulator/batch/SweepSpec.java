package rp1.simulator.batch;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;

import rp1.io.IoFailures;

/**
 * What decides a sweep's runs and their rows: the properties' text, the floor plans (names and text),
 * the seeds, the varied keys and their values, the {@code --client}, the robot's code ({@link RobotCode})
 * and the timeout; not {@code --jobs}
 * or {@code --isolation}, which only decide how the runs are carried out. Kept in the
 * output folder as {@code sweep.ini}, so that {@code --resume} goes on only with the sweep that
 * folder holds. Immutable.
 */
final class SweepSpec {
    /** The file in the output folder. */
    static final String FILE = "sweep.ini";
    private static final String FORMAT = "rp1-sweep";
    /** How {@link #differences} names a difference of format (an earlier version of RP1 wrote the file). */
    static final String FORMAT_NAME = "the format of " + FILE;
    /** What each key is called in a message, in the order they are written. */
    private static final Map<String, String> NAMES = names();

    private final Map<String, String> values;

    private SweepSpec(Map<String, String> values) {
        this.values = values;
    }

    private static Map<String, String> names() {
        Map<String, String> names = new LinkedHashMap<>();
        names.put(FORMAT, FORMAT_NAME);
        names.put("properties.sha256", "the properties' text (-p)");
        names.put("plans", "the floor plans (--plans)");
        names.put("plans.sha256", "the floor plans' text, and the walls their map images give");
        names.put("seeds", "the seeds (--seeds)");
        names.put("vary", "the varied keys (--vary)");
        names.put("client", "the client program (--client)");
        names.put("robot.crc32", "the robot's code (its classes, or the files the --client command names)");
        names.put("timeout", "the timeout (--timeout)");
        return names;
    }

    /** The specification of the sweep {@code options} ask for, with these properties and plans (name to text). */
    static SweepSpec of(String propertiesText, Map<String, String> plans, SweepOptions options, String robotCode) {
        Map<String, String> v = new LinkedHashMap<>();
        v.put(FORMAT, "3");
        v.put("properties.sha256", sha256(propertiesText));
        v.put("plans", String.join(",", plans.keySet()));
        StringBuilder planTexts = new StringBuilder();
        plans.forEach((name, text) -> planTexts.append(name).append('\0').append(text).append('\0'));
        v.put("plans.sha256", sha256(planTexts.toString()));
        v.put("seeds", options.seeds.stream().map(String::valueOf).collect(Collectors.joining(",")));
        v.put("vary", options.varied.stream().map(Varied::toString).collect(Collectors.joining(" ")));
        v.put("client", options.client == null ? "" : options.client);
        v.put("robot.crc32", robotCode);
        v.put("timeout", Double.toString(options.timeoutSeconds));
        return new SweepSpec(v);
    }

    /** Writes {@code sweep.ini} into {@code dir}, replacing it. */
    void write(Path dir) throws IOException {
        StringBuilder b = new StringBuilder("# The sweep whose runs this folder holds; rp1.Sweep --resume goes on with"
                + " this one only\n");
        values.forEach((k, v) -> b.append(k).append('=').append(v).append('\n'));
        Files.write(dir.resolve(FILE), b.toString().getBytes(StandardCharsets.UTF_8));
    }

    /**
     * The specification kept in {@code dir}.
     *
     * @throws SweepException if there is none (no sweep ran there) or it cannot be read
     */
    static SweepSpec read(Path dir) throws SweepException {
        List<String> lines;
        try {
            lines = Files.readAllLines(dir.resolve(FILE), StandardCharsets.UTF_8);
        } catch (NoSuchFileException e) {
            throw new SweepException("--resume: " + dir + " holds no sweep to go on with (it has no " + FILE + ")");
        } catch (IOException e) {
            throw new SweepException("--resume: cannot read " + dir.resolve(FILE) + ": " + IoFailures.why(e));
        }
        Map<String, String> v = new LinkedHashMap<>();
        for (String line : lines) {
            int eq = line.indexOf('=');
            if (!line.startsWith("#") && eq > 0) {
                v.put(line.substring(0, eq), line.substring(eq + 1));
            }
        }
        return new SweepSpec(v);
    }

    /** What differs from {@code here}, as "NAME: there A, here B" phrases; empty if nothing does. */
    List<String> differences(SweepSpec here) {
        List<String> d = new ArrayList<>();
        for (Map.Entry<String, String> key : NAMES.entrySet()) {
            String there = values.get(key.getKey());
            String now = here.values.get(key.getKey());
            if (!now.equals(there)) {
                int from = firstDifference(there, now) > 30 ? firstDifference(there, now) - 20 : 0;
                d.add(key.getKey().endsWith(".sha256") || key.getKey().endsWith(".crc32") ? key.getValue() + " is not the same"
                        : key.getValue() + ": " + shown(there, from) + " there, " + shown(now, from) + " here");
            }
        }
        return d;
    }

    /** Where two values first differ (0 if either is missing). */
    private static int firstDifference(String a, String b) {
        if (a == null || b == null) {
            return 0;
        }
        int i = 0;
        while (i < a.length() && i < b.length() && a.charAt(i) == b.charAt(i)) {
            i++;
        }
        return i;
    }

    /**
     * A value as the message shows it: from {@code from} on (a little before where two long values part,
     * so that the difference is in sight), and at most 60 characters.
     */
    private static String shown(String value, int from) {
        if (value == null) {
            return "none";
        }
        String shown = from > 0 && from < value.length() ? "..." + value.substring(from) : value;
        return shown.length() > 60 ? shown.substring(0, 57) + "..." : shown;
    }

    /** Computes a digest of nothing: the first digest in a JVM sets up the JDK's security providers. */
    static void warmUp() {
        sha256("");
    }

    private static String sha256(String text) {
        try {
            return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(text.getBytes(StandardCharsets.UTF_8)));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("every Java has SHA-256", e);
        }
    }
}
