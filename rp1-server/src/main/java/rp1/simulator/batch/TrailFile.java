package rp1.simulator.batch;

import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import rp1.simulator.outcome.Trail;

/**
 * The robots' trails of one run, as the run leaves them in {@code trails.txt} for the sweep's
 * summary picture: a line {@code robot NAME} per robot, then its pieces of path, each a line
 * {@code piece} followed by one line {@code x y} per point.
 */
public final class TrailFile {
    /** The file a run leaves in its folder. */
    public static final String FILE = "trails.txt";

    private TrailFile() {
    }

    /** Writes {@code trails} into {@code dir}, coordinates to 0.1 mm (the points are a centimetre apart). */
    public static void write(Path dir, List<Trail> trails) throws IOException {
        StringBuilder b = new StringBuilder();
        for (Trail t : trails) {
            b.append("robot ").append(t.robot().replace('\n', ' ')).append('\n');
            for (double[] piece : t.pieces()) {
                b.append("piece\n");
                for (int i = 0; i + 1 < piece.length; i += 2) {
                    tenthsOfMillimetres(b, piece[i]).append(' ');
                    tenthsOfMillimetres(b, piece[i + 1]).append('\n');
                }
            }
        }
        try (Writer out = Files.newBufferedWriter(dir.resolve(FILE), StandardCharsets.UTF_8)) {
            out.append(b);
        }
    }

    /** {@code metres} with four decimals, without the cost of general number formatting (a run has thousands). */
    private static StringBuilder tenthsOfMillimetres(StringBuilder b, double metres) {
        long n = Math.round(metres * 1e4);
        if (n < 0) {
            b.append('-');
            n = -n;
        }
        long fraction = n % 10_000;
        b.append(n / 10_000).append('.');
        for (long digit = 1000; digit > 1 && fraction < digit; digit /= 10) {
            b.append('0');
        }
        return b.append(fraction);
    }

    /**
     * Reads the trails a run left in {@code dir} (none if it left no file).
     *
     * @throws IOException if the file is not one this class wrote
     */
    public static List<Trail> read(Path dir) throws IOException {
        Path file = dir.resolve(FILE);
        List<Trail> trails = new ArrayList<>();
        if (!Files.exists(file)) {
            return trails;
        }
        String robot = null;
        List<double[]> pieces = new ArrayList<>();
        List<Double> piece = null;
        for (String line : Files.readAllLines(file, StandardCharsets.UTF_8)) {
            if (line.startsWith("robot ")) {
                add(trails, robot, pieces, piece);
                robot = line.substring(6);
                pieces = new ArrayList<>();
                piece = null;
            } else if (line.equals("piece") && robot != null) {
                add(pieces, piece);
                piece = new ArrayList<>();
            } else if (piece != null) {
                point(file, line, piece);
            } else {
                throw new IOException(file + ": not a trail file: \"" + line + "\"");
            }
        }
        add(trails, robot, pieces, piece);
        return trails;
    }

    private static void point(Path file, String line, List<Double> piece) throws IOException {
        String[] xy = line.split(" ");
        try {
            piece.add(Double.parseDouble(xy[0]));
            piece.add(Double.parseDouble(xy[1]));
        } catch (NumberFormatException | ArrayIndexOutOfBoundsException e) {
            throw new IOException(file + ": not a point: \"" + line + "\"", e);
        }
    }

    private static void add(List<Trail> trails, String robot, List<double[]> pieces, List<Double> piece) {
        if (robot != null) {
            add(pieces, piece);
            trails.add(new Trail(robot, pieces));
        }
    }

    private static void add(List<double[]> pieces, List<Double> piece) {
        if (piece != null) {
            pieces.add(Trail.piece(piece));
        }
    }
}
