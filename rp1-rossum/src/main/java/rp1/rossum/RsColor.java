package rp1.rossum;

import java.awt.Color;
import java.util.Arrays;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The colour names of the floor-plan language (case-sensitive, as {@code java.awt.Color} spells its
 * constants) and helpers for the colour lists painters use.
 */
public class RsColor {
    private static final Map<String, Color> BY_NAME;

    static {
        Map<String, Color> m = new LinkedHashMap<>();
        m.put("black", new Color(0, 0, 0));
        m.put("blue", new Color(0, 0, 255));
        m.put("cyan", new Color(0, 255, 255));
        m.put("darkGray", new Color(64, 64, 64));
        m.put("gray", new Color(128, 128, 128));
        m.put("green", new Color(0, 255, 0));
        m.put("lightGray", new Color(192, 192, 192));
        m.put("magenta", new Color(255, 0, 255));
        m.put("orange", new Color(255, 200, 0));
        m.put("pink", new Color(255, 175, 175));
        m.put("red", new Color(255, 0, 0));
        m.put("white", new Color(255, 255, 255));
        m.put("yellow", new Color(255, 255, 0));
        BY_NAME = Collections.unmodifiableMap(m);
    }

    /**
     * An instance has no state: everything is in the static methods. Kept for programs written
     * against 0.60.
     */
    public RsColor() {
    }

    /** The colour with this exact (case-sensitive) name, or null if the name is not one of the thirteen. */
    public static Color getColorForName(String name) {
        return name == null ? null : BY_NAME.get(name);
    }

    /** The name of a colour equal (in RGB) to one of the named colours, or null. */
    public static String getNameForColor(Color color) {
        if (color == null) {
            return null;
        }
        for (Map.Entry<String, Color> e : BY_NAME.entrySet()) {
            if (e.getValue().getRGB() == color.getRGB()) {
                return e.getKey();
            }
        }
        return null;
    }

    /** The colour names, in alphabetical order. */
    public static String[] getColorNames() {
        return BY_NAME.keySet().toArray(new String[0]);
    }

    /** Whether two colour lists hold the same colours in the same order (two nulls are the same). */
    public static boolean areColorListsTheSame(Color[] a, Color[] b) {
        return Arrays.equals(a, b);
    }

    /** A copy of the list (colours are immutable, so they are shared); null stays null. */
    public static Color[] copyColorList(Color[] colors) {
        return colors == null ? null : colors.clone();
    }
}
