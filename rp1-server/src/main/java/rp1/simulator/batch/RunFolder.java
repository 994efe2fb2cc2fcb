package rp1.simulator.batch;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Pattern;

import rp1.simulator.outcome.Trail;

/**
 * A run's folder: written before the run (its {@code run.ini}, the user's properties with the run's
 * own keys after them, and its {@code --client} command), read after it (its trails). Nothing an
 * earlier run left there is taken for this run's.
 */
final class RunFolder {
    /** Each run's recording, event log and end picture, in its folder (docs/guide.md names them). */
    private static final String RECORDING = "recording.txt";
    private static final String EVENTS = "events.txt";
    private static final String PICTURE = "end.png";

    /** The keys a {@code --client} sets: its program is the robot, over the network (in this order in run.ini). */
    static final Map<String, String> CLIENT_KEYS = clientKeys();

    private static Map<String, String> clientKeys() {
        Map<String, String> keys = new LinkedHashMap<>();
        keys.put("enableNetworkClients", "true");
        keys.put("dlcEnabled", "false");
        keys.put("exitWhenClientsDone", "false");
        return Collections.unmodifiableMap(keys);
    }

    /** What of the user's properties every run's begin with: without snapshotFileName unless --pictures. */
    private final String runPropertiesText;
    private final String client;
    private final boolean pictures;

    /**
     * @param propertiesText the user's properties, as written
     * @param client         the {@code --client} command, or null
     * @param pictures       whether each run writes the picture of its end ({@code --pictures})
     */
    RunFolder(String propertiesText, String client, boolean pictures) {
        // An empty value is refused as a typo, so "no picture" is the user's snapshotFileName left out.
        this.runPropertiesText = pictures ? propertiesText : withoutKey(propertiesText, "snapshotFileName");
        this.client = client;
        this.pictures = pictures;
    }

    /** The run's folder with its properties (and --client command), and nothing an earlier run left. */
    void prepare(Batch.Run run) throws IOException {
        Files.createDirectories(run.dir());
        forgetOutcome(run);
        Files.write(run.dir().resolve(SweepRun.PROPERTIES), properties(run).getBytes(StandardCharsets.UTF_8));
        Path command = run.dir().resolve(SweepRun.CLIENT_COMMAND);
        if (client != null) {
            Files.write(command, (client + "\n").getBytes(StandardCharsets.UTF_8));
        } else {
            Files.deleteIfExists(command);
        }
    }

    /**
     * Deletes the report and trails a run left in its folder, so that a run carried out there again
     * which ends without writing its own is not taken to have ended as the one before.
     */
    static void forgetOutcome(Batch.Run run) throws IOException {
        Files.deleteIfExists(run.dir().resolve(RunReport.FILE));
        Files.deleteIfExists(run.dir().resolve(TrailFile.FILE));
    }

    /** The trails a run left in its folder; none if it left none, or none that can be read (told on standard error). */
    static List<Trail> trails(Batch.Run run) {
        try {
            return TrailFile.read(run.dir());
        } catch (IOException e) {
            // Not a reason to lose the run's row, but summary.png will lack its trails: say so.
            System.err.println("rp1.Sweep: " + run.dir().resolve(TrailFile.FILE) + ": " + e.getMessage()
                    + "; the run's trails are left out of summary.png");
            return List.of();
        }
    }

    /**
     * The user's properties with the run's own keys after them (later keys win): its configuration,
     * a {@code --client}'s keys, its seed and plan, no window and no live view, and its log, recording, event log and
     * (with {@code --pictures}) picture in its folder; without, none, since drawing and encoding it
     * would cost a bumper run three times what the run itself costs (a replay draws one when asked).
     */
    private String properties(Batch.Run run) {
        Path d = run.dir().toAbsolutePath();
        // Escaped as a properties file escapes them: a varied value a\b, or a plan's Windows path, is
        // read back as written.
        Map<String, String> own = new LinkedHashMap<>(run.configuration());
        if (client != null) {
            own.putAll(CLIENT_KEYS);
        }
        own.put("randomSeed", Long.toString(run.seed()));
        own.put("floorPlanFileName", run.plan());
        own.put("enableGUI", "false");
        // Runs go side by side: a live view on one port would let only the first of them start.
        own.put("viewPort", "0");
        own.put("logToFile", "true");
        own.put("logFileName", d.resolve(SweepRun.LOG).toString());
        own.put("logToSystemOut", "false");
        own.put("recordFileName", d.resolve(RECORDING).toString());
        own.put("eventLogFileName", d.resolve(EVENTS).toString());
        if (pictures) {
            own.put("snapshotFileName", d.resolve(PICTURE).toString());
        }
        own.put("snapshotInterval", "0");
        return runPropertiesText + "\n\n# rp1.Sweep: seed " + run.seed() + " on " + run.plan() + Batch.describe(run.configuration())
                + "\n" + PropertiesText.of(own);
    }

    /** The properties text without the lines that set {@code key} (and the lines such a line continues onto). */
    static String withoutKey(String text, String key) {
        StringBuilder kept = new StringBuilder();
        boolean dropping = false;
        Pattern setting = Pattern.compile(Pattern.quote(key) + "\\s*[=:\\s].*|" + Pattern.quote(key));
        for (String line : text.split("\n", -1)) {
            String t = line.stripLeading();
            boolean continues = line.endsWith("\\");
            if (dropping || setting.matcher(t).matches()) {
                dropping = continues;
                continue;
            }
            kept.append(line).append('\n');
        }
        return kept.toString();
    }
}
