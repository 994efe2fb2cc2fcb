package rp1.spark;

import java.io.Serializable;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * What one run on an executor sends back to the driver in its task's result: its small files (and
 * those asked for with {@code --keep}) by name, and the names of those left out as too large.
 */
final class RunFiles implements Serializable {
    private static final long serialVersionUID = 1L;

    /** File name to content, in the order found. */
    final Map<String, byte[]> files;
    /** "NAME (N bytes)" of each file not sent. */
    final List<String> leftOut;
    /** The executor's host, for the run's folder (where a run went is worth knowing when one fails). */
    final String host;

    RunFiles(Map<String, byte[]> files, List<String> leftOut, String host) {
        this.files = new LinkedHashMap<>(files);
        this.leftOut = List.copyOf(leftOut);
        this.host = host;
    }
}
