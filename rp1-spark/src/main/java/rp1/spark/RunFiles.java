package rp1.spark;

import java.io.Serializable;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import rp1.simulator.outcome.Trail;

/**
 * What one run on an executor sends back to the driver in its task's result: its report and small
 * files (and those asked for with {@code --keep}) by name, the names of those left out as too large,
 * and its trails.
 */
final class RunFiles implements Serializable {
    private static final long serialVersionUID = 1L;

    /** File name to content, in the order found. */
    final Map<String, byte[]> files;
    /** The size in bytes of each file not sent, by name, in the order found. */
    final Map<String, Long> leftOut;
    /** The executor's host, for the run's folder (where a run went is worth knowing when one fails). */
    final String host;
    /** Each robot's name and its trail's pieces, as the run handed them over. */
    private final List<String> trailRobots = new ArrayList<>();
    private final List<ArrayList<double[]>> trailPieces = new ArrayList<>();

    RunFiles(Map<String, byte[]> files, Map<String, Long> leftOut, String host, List<Trail> trails) {
        this.files = new LinkedHashMap<>(files);
        this.leftOut = new LinkedHashMap<>(leftOut);
        this.host = host;
        for (Trail t : trails) {
            trailRobots.add(t.robot());
            trailPieces.add(new ArrayList<>(t.pieces()));
        }
    }

    /** The run's trails, as its engine handed them over on the executor. */
    List<Trail> trails() {
        List<Trail> trails = new ArrayList<>();
        for (int i = 0; i < trailRobots.size(); i++) {
            trails.add(new Trail(trailRobots.get(i), trailPieces.get(i)));
        }
        return trails;
    }
}
