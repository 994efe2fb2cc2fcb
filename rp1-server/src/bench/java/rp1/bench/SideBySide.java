package rp1.bench;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.OptionalDouble;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * {@code gradle bench -PbenchArgs="peers[=DIR] [robots=1000] [rounds=4]"}: the scale arena side by side
 * with the peer simulators (docs/performance.md, "The scale arena, side by side"), in one sitting. A
 * figure from another day says little on a shared machine, where the same build reads a quarter apart
 * from one hour to the next; a ratio of two runs back to back says what the issue asks. Each round
 * runs, for every robot count, Stage's {@code stage_bench.sh N SECONDS} and {@link ScaleArena} over the
 * same simulated span, alternating which goes first, and prints both figures and their ratio; at the
 * end, per robot count, the medians and every round's ratio, as a table to quote.
 *
 * <p>The peers are not part of the project: DIR (or {@code $RP1_PEERS}) is the folder of their scripts,
 * whose own {@code setup.sh} builds them. Without it this part says so and measures nothing. ir-sim
 * ({@code irsim_bench.sh}) runs too for counts up to 100, as the peers' own table has it: it is the
 * slow one (6.3 simulated s per wall s at 100 robots here, 48 s for one round's 300 simulated seconds).
 */
final class SideBySide {
    /** The environment variable naming the peers' folder when the argument does not. */
    static final String PEERS_VARIABLE = "RP1_PEERS";
    /** ir-sim runs up to this many robots, as the peers' own table has it. */
    private static final int IRSIM_MOST = 100;
    private static final Pattern RP1_FIGURE = Pattern.compile("([0-9][0-9,]*\\.[0-9]+) simulated s per wall s");
    private static final Pattern PEER_FIGURE = Pattern.compile("loop-only ([0-9.]+)");

    private SideBySide() {
    }

    /** A peer's benchmark script, its name in the table, and up to how many robots it is run. */
    record Peer(String name, Path script, int most) {
    }

    /** One round's figures for one robot count: simulated seconds per wall second (NaN: failed). */
    record Round(double rp1, double[] peers) {
    }

    /**
     * The peers' folder: {@code given} if not null, else {@code variable} ({@code $RP1_PEERS}) if set;
     * null if that is not a folder with Stage's script.
     */
    static Path peersFolder(String given, String variable) {
        String named = given != null ? given : variable;
        if (named == null || named.isEmpty()) {
            return null;
        }
        Path p = Paths.get(named);
        return Files.isRegularFile(p.resolve("stage_bench.sh")) ? p.toAbsolutePath().normalize() : null;
    }

    /** Runs {@code rounds} rounds over {@code robots}, the peers' scripts from {@code folder}. */
    static void run(Path folder, List<Integer> robots, int rounds, String xmx) throws IOException, InterruptedException {
        if (folder == null) {
            System.out.println("peers: no peers' folder with stage_bench.sh (give it as peers=DIR or $" + PEERS_VARIABLE
                    + "); nothing measured. The peers are built by their own setup.sh.");
            return;
        }
        List<Peer> peers = List.of(new Peer("Stage 4.3.0 (loop-only)", folder.resolve("stage_bench.sh"), Integer.MAX_VALUE),
                new Peer("ir-sim 2.12.0 (loop-only)", folder.resolve("irsim_bench.sh"), IRSIM_MOST));
        System.out.printf(Locale.ROOT, "peers: %s, %d round(s), robots %s; each round alternates which goes first%n",
                folder, rounds, robots);
        List<List<Round>> all = new ArrayList<>();
        for (int n : robots) {
            all.add(new ArrayList<>());
        }
        for (int k = 0; k < rounds; k++) {
            for (int i = 0; i < robots.size(); i++) {
                int n = robots.get(i);
                boolean rp1First = k % 2 == 1;
                double rp1 = rp1First ? rp1(n, xmx) : Double.NaN;
                double[] figures = new double[peers.size()];
                for (int j = 0; j < peers.size(); j++) {
                    figures[j] = n <= peers.get(j).most() ? peer(peers.get(j), n) : Double.NaN;
                }
                if (!rp1First) {
                    rp1 = rp1(n, xmx);
                }
                all.get(i).add(new Round(rp1, figures));
                StringBuilder line = new StringBuilder(String.format(Locale.ROOT, "round %d, %,d robots: RP1 %s",
                        k + 1, n, figure(rp1)));
                for (int j = 0; j < peers.size(); j++) {
                    if (!Double.isNaN(figures[j])) {
                        line.append(String.format(Locale.ROOT, ", %s %s, RP1 / it %s", peers.get(j).name(),
                                figure(figures[j]), ratio(rp1, figures[j])));
                    }
                }
                System.out.println(line);
            }
        }
        System.out.println();
        System.out.println(table(robots, peers, all));
    }

    /** The summary: per robot count, the medians and every round's ratio to Stage. */
    static String table(List<Integer> robots, List<Peer> peers, List<List<Round>> all) {
        StringBuilder t = new StringBuilder("| Robots | RP1, median (rounds) |");
        for (Peer p : peers) {
            t.append(' ').append(p.name()).append(", median |");
        }
        t.append(" RP1 / ").append(peers.get(0).name().replaceFirst(" .*", "")).append(", by round (median) |\n|---|---|");
        t.append("---|".repeat(peers.size())).append("---|\n");
        for (int i = 0; i < robots.size(); i++) {
            List<Round> rounds = all.get(i);
            double[] rp1 = rounds.stream().mapToDouble(Round::rp1).toArray();
            t.append(String.format(Locale.ROOT, "| %,d | %s (%s) |", robots.get(i), figure(median(rp1)), list(rp1)));
            for (int j = 0; j < peers.size(); j++) {
                int at = j;
                t.append(' ').append(figure(median(rounds.stream().mapToDouble(r -> r.peers()[at]).toArray()))).append(" |");
            }
            double[] ratios = rounds.stream().mapToDouble(r -> r.rp1() / r.peers()[0]).toArray();
            t.append(' ').append(list(ratios)).append(" (").append(figure(median(ratios))).append(") |\n");
        }
        return t.toString();
    }

    /** The median of the numbers that are not NaN; NaN if none is. */
    static double median(double[] values) {
        double[] v = Arrays.stream(values).filter(d -> !Double.isNaN(d)).sorted().toArray();
        if (v.length == 0) {
            return Double.NaN;
        }
        return v.length % 2 == 1 ? v[v.length / 2] : (v[v.length / 2 - 1] + v[v.length / 2]) / 2;
    }

    private static String list(double[] values) {
        StringBuilder s = new StringBuilder();
        for (double v : values) {
            s.append(s.length() == 0 ? "" : ", ").append(figure(v));
        }
        return s.toString();
    }

    /** Three significant digits at least, no exponent: 123,000, 931, 37.0, 5.13; "—" for none. */
    static String figure(double v) {
        if (Double.isNaN(v) || Double.isInfinite(v)) {
            return "—";
        }
        double a = Math.abs(v);
        return a >= 1000 ? String.format(Locale.ROOT, "%,.0f", v) : a >= 100 ? String.format(Locale.ROOT, "%.0f", v)
                : a >= 10 ? String.format(Locale.ROOT, "%.1f", v) : String.format(Locale.ROOT, "%.2f", v);
    }

    private static String ratio(double a, double b) {
        return figure(a / b);
    }

    /** RP1's steady-state figure for {@code n} robots, as {@code gradle bench}'s scale part measures it. */
    private static double rp1(int n, String xmx) throws IOException, InterruptedException {
        List<String> lines = new ArrayList<>();
        int status = Child.run(xmx, ScaleArena.class, lines::add, String.valueOf(n),
                String.valueOf(ScaleArena.simulatedFor(n)), String.valueOf(ScaleArena.arenaFor(n)));
        return figure("RP1", n, status, lines, RP1_FIGURE);
    }

    /** The peer's loop-only figure for {@code n} robots over the same simulated span as RP1's. */
    private static double peer(Peer p, int n) throws IOException, InterruptedException {
        if (!Files.isRegularFile(p.script())) {
            return Double.NaN;
        }
        List<String> lines = new ArrayList<>();
        int status = Child.run(List.of("bash", p.script().toString(), String.valueOf(n),
                String.valueOf((long) ScaleArena.simulatedFor(n))), lines::add);
        return figure(p.name() + " (is it built? its setup.sh builds it)", n, status, lines, PEER_FIGURE);
    }

    /** The figure a run printed, or NaN, saying why, if it failed or printed none. */
    private static double figure(String who, int n, int status, List<String> lines, Pattern pattern) {
        OptionalDouble f = status == 0 ? parse(lines, pattern) : OptionalDouble.empty();
        if (f.isEmpty()) {
            System.out.println(who + ", " + n + " robots: no figure (status " + status + "): " + String.join(" / ", lines));
        }
        return f.orElse(Double.NaN);
    }

    /** The last figure {@code pattern} finds in {@code lines}. */
    static OptionalDouble parse(List<String> lines, Pattern pattern) {
        OptionalDouble found = OptionalDouble.empty();
        for (String line : lines) {
            Matcher m = pattern.matcher(line);
            if (m.find()) {
                found = OptionalDouble.of(Double.parseDouble(m.group(1).replace(",", "")));
            }
        }
        return found;
    }
}
