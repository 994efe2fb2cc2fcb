package rp1.simulator.config;

import java.util.Collection;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * What a mistyped word on a command line was most likely meant to be: "unknown option --sed; did you
 * mean --seeds?". Only a near candidate is offered (a slip of the keys, not a guess), and the
 * candidates are read off the command's own usage text, so an option added there is offered too.
 */
public final class Suggestion {
    /** An option as a usage text writes it: -p, --seeds, -classpath. */
    private static final Pattern OPTION = Pattern.compile("(?<![\\w-])--?[a-zA-Z][\\w-]*");

    private Suggestion() {
    }

    /**
     * The candidate nearest {@code word} in edit distance, letter case ignored, if it is within a third
     * of the word's length (at least 2, at most 3); else null, and always for words of under four
     * characters ({@code -x} is no slip of {@code -p}).
     */
    public static String nearest(String word, Collection<String> candidates) {
        if (word.length() < 4) {
            return null;
        }
        int allowed = Math.min(3, Math.max(2, word.length() / 3));
        String best = null;
        int bestDistance = Integer.MAX_VALUE;
        for (String c : candidates) {
            int d = PropertyKeys.distance(word.toLowerCase(Locale.ROOT), c.toLowerCase(Locale.ROOT));
            if (d < bestDistance && d <= allowed && !c.equals(word)) {
                best = c;
                bestDistance = d;
            }
        }
        return best;
    }

    /** "; did you mean X?" for the candidate {@link #nearest} finds, or "" if none is near. */
    public static String didYouMean(String word, Collection<String> candidates) {
        String meant = nearest(word, candidates);
        return meant == null ? "" : "; did you mean " + meant + "?";
    }

    /** The options a usage text names, once each, in the order it names them. */
    public static List<String> optionsIn(String usage) {
        Set<String> found = new LinkedHashSet<>();
        Matcher m = OPTION.matcher(usage);
        while (m.find()) {
            found.add(m.group());
        }
        return List.copyOf(found);
    }
}
