package rp1.simulator.batch;

import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * One {@code --vary KEY=...} of a sweep: a properties key and the values it takes, either listed
 * ({@code KEY=V1,V2,...}, each once: two spellings of one number are refused) or a numeric range
 * ({@code KEY=FROM:TO:STEP}, both ends included, the steps reaching TO exactly, computed in decimal
 * so that {@code 0.1:0.3:0.1} gives {@code 0.1,0.2,0.3}).
 *
 * @param key    the properties key; {@code param.NAME} is a parameter of the robot
 * @param values the values, in the order given, each once
 */
public record Varied(String key, List<String> values) {
    /** The keys a sweep sets for each run itself, and the option that varies them instead. */
    private static final List<String[]> OWN_KEYS = List.of(new String[] {"randomSeed", "--seeds"},
            new String[] {"floorPlanFileName", "--plans"}, new String[] {"recordFileName", null},
            new String[] {"eventLogFileName", null}, new String[] {"snapshotFileName", null},
            new String[] {"logFileName", null}, new String[] {"enableGUI", null}, new String[] {"viewPort", null});

    /** Copies the list. */
    public Varied {
        values = List.copyOf(values);
    }

    /**
     * Parses {@code KEY=V1,V2,...} or {@code KEY=FROM:TO:STEP}.
     *
     * @throws IllegalArgumentException saying what is wrong with {@code spec}
     */
    static Varied parse(String spec) {
        int eq = spec.indexOf('=');
        String key = eq < 0 ? "" : spec.substring(0, eq).trim();
        if (eq <= 0 || key.isEmpty() || !key.matches("[A-Za-z0-9_.-]+")) {
            throw new IllegalArgumentException("--vary " + spec + ": KEY=V1,V2,... or KEY=FROM:TO:STEP expected, KEY"
                    + " being a properties key (letters, digits, _, . or -)");
        }
        for (String[] own : OWN_KEYS) {
            if (own[0].equals(key)) {
                throw new IllegalArgumentException("--vary " + key + ": the sweep sets " + key + " for each run itself"
                        + (own[1] == null ? "" : "; use " + own[1]));
            }
        }
        String rest = spec.substring(eq + 1).trim();
        List<String> values = rest.contains(":") ? range(spec, rest) : list(spec, rest);
        return new Varied(key, values);
    }

    private static List<String> list(String spec, String rest) {
        Set<String> values = new LinkedHashSet<>();
        for (String v : rest.split(",", -1)) {
            if (v.trim().isEmpty() || v.trim().matches(".*\\s.*")) {
                throw new IllegalArgumentException("--vary " + spec + ": \"" + v + "\" is not a value (values are"
                        + " separated by commas and hold no white space)");
            }
            String same = sameNumber(values, v.trim());
            if (same != null) {
                // Two configurations that differ by their spelling alone would be one counted twice.
                throw new IllegalArgumentException("--vary " + spec + ": " + v.trim() + " is " + same + " again");
            }
            values.add(v.trim());
        }
        return new ArrayList<>(values);
    }

    /** The value of {@code values} that is the same number as {@code v} written otherwise, or null. */
    private static String sameNumber(Set<String> values, String v) {
        BigDecimal n = number(v);
        if (n == null) {
            return null;
        }
        for (String w : values) {
            BigDecimal m = number(w);
            if (m != null && m.compareTo(n) == 0 && !w.equals(v)) {
                return w;
            }
        }
        return null;
    }

    private static BigDecimal number(String s) {
        try {
            return new BigDecimal(s);
        } catch (NumberFormatException e) {
            return null;
        }
    }

    private static List<String> range(String spec, String rest) {
        String[] parts = rest.split(":", -1);
        if (parts.length != 3) {
            throw new IllegalArgumentException("--vary " + spec + ": a range is FROM:TO:STEP");
        }
        BigDecimal from = decimal(spec, parts[0]);
        BigDecimal to = decimal(spec, parts[1]);
        BigDecimal step = decimal(spec, parts[2]);
        if (step.signum() <= 0 || to.compareTo(from) < 0) {
            throw new IllegalArgumentException("--vary " + spec + ": a range needs FROM <= TO and a positive STEP");
        }
        if (to.subtract(from).remainder(step).signum() != 0) {
            BigDecimal last = from.add(step.multiply(to.subtract(from).divideToIntegralValue(step)));
            throw new IllegalArgumentException("--vary " + spec + ": the steps from " + parts[0].trim() + " by "
                    + parts[2].trim() + " do not reach " + parts[1].trim() + " (the last below it is "
                    + last.stripTrailingZeros().toPlainString() + "): give a TO they reach, both ends being run");
        }
        List<String> values = new ArrayList<>();
        for (BigDecimal v = from; v.compareTo(to) <= 0; v = v.add(step)) {
            if (values.size() >= SweepOptions.MAX_RUNS) {
                throw new IllegalArgumentException("--vary " + spec + ": more than " + SweepOptions.MAX_RUNS + " values");
            }
            values.add(v.stripTrailingZeros().toPlainString());
        }
        return values;
    }

    private static BigDecimal decimal(String spec, String s) {
        try {
            return new BigDecimal(s.trim());
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("--vary " + spec + ": \"" + s + "\" is not a number");
        }
    }

    /**
     * Every configuration of {@code varied}: the full product of their values, the first key varying
     * slowest; one empty configuration when nothing varies.
     */
    static List<Map<String, String>> product(List<Varied> varied) {
        List<Map<String, String>> out = new ArrayList<>();
        out.add(new LinkedHashMap<>());
        for (Varied v : varied) {
            List<Map<String, String>> next = new ArrayList<>();
            for (Map<String, String> c : out) {
                for (String value : v.values()) {
                    Map<String, String> d = new LinkedHashMap<>(c);
                    d.put(v.key(), value);
                    next.add(d);
                }
            }
            out = next;
        }
        return out;
    }

    /** {@code KEY=V1,V2,...}, as the values were taken. */
    @Override
    public String toString() {
        return key + "=" + String.join(",", values);
    }
}
