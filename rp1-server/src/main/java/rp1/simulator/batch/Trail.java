package rp1.simulator.batch;

import java.util.List;

/**
 * Where one robot went in a run: pieces of path in world metres, each {@code x0, y0, x1, y1, ...}; a
 * new piece begins wherever the robot was placed anew.
 */
public record Trail(String robot, List<double[]> pieces) {
    /** Copies the list (the arrays are not changed once a trail is made). */
    public Trail {
        pieces = List.copyOf(pieces);
    }

    /** A piece of path from its coordinates {@code x0, y0, x1, y1, ...}. */
    static double[] piece(List<Double> xy) {
        double[] out = new double[xy.size()];
        for (int i = 0; i < out.length; i++) {
            out[i] = xy.get(i);
        }
        return out;
    }
}
