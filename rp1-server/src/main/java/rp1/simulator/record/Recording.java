package rp1.simulator.record;

import java.util.List;
import java.util.Map;
import java.util.Properties;

import rp1.simulator.ViewAction;
import rp1.simulator.session.Request;

/**
 * A recording read back (docs/recording.md): what the run started from, its clients, its inputs in
 * the order they were applied, and how it ended. Immutable.
 *
 * @param file       the file it was read from, for messages
 * @param seed       the seed of the run's random source
 * @param properties the properties as they took effect
 * @param planName   where the floor plan was read from (errors and the plan name it)
 * @param planText   the floor plan's text
 * @param clients    client number to the description the run gave it
 * @param steps      the inputs, in the order the run applied them
 * @param end        how the run ended, or null if the recording has no end (the run did not stop cleanly)
 * @param tornLine   the number of the last line if it was cut off while being written (the run was
 *                   killed) and so left out; 0 if the file ends with a whole line
 */
public record Recording(String file, long seed, Map<String, String> properties, String planName, String planText,
                        Map<Integer, String> clients, List<Step> steps, End end, int tornLine) {

    /** Copies the collections. */
    public Recording {
        properties = Map.copyOf(properties);
        clients = Map.copyOf(clients);
        steps = List.copyOf(steps);
    }

    /**
     * One input: applied after {@code task} model tasks had run, at simulated time {@code time}, from
     * client {@code source} (a {@code request}) or from the view (source 0, an {@code action}).
     *
     * @param line the line of the recording it was read from
     */
    public record Step(int line, long task, double time, int source, Request request, ViewAction action) {
    }

    /**
     * The end of the run: {@code tasks} model tasks had run, the time was {@code time}, and
     * {@code events} events had been sent, whose lines have CRC-32 {@code checksum}.
     */
    public record End(int line, long tasks, double time, long events, long checksum) {
    }

    /** The properties as a table, as the server read them. */
    public Properties propertiesTable() {
        Properties p = new Properties();
        p.putAll(properties);
        return p;
    }

    /** The highest client number in the recording (0 if none). */
    public int maxClient() {
        int max = 0;
        for (int n : clients.keySet()) {
            max = Math.max(max, n);
        }
        return max;
    }
}
