package rp1.simulator.config;

import java.util.Collections;
import java.util.Locale;
import java.util.Properties;
import java.util.SortedMap;
import java.util.TreeMap;

import rp1.rossum.RsProperties;

/**
 * Typed, validated access to a properties table read from one source (a file or class-path
 * resource). Only the first white-space-delimited word of a value counts, as in RP1 0.60, so trailing
 * comments are harmless. Errors name the key, the value and the source. Only keys declared in
 * {@link PropertyKeys} can be read: the same table then tells a known key from a misspelt one.
 */
final class PropertyReader {
    private final Properties table;
    private final String source;
    private final PropertyKeys keys;

    PropertyReader(Properties table, String source, PropertyKeys keys) {
        this.table = table;
        this.source = source;
        this.keys = keys;
    }

    String source() {
        return source;
    }

    /** Every key and its value as given, sorted by key. */
    SortedMap<String, String> given() {
        SortedMap<String, String> all = new TreeMap<>();
        for (String key : table.stringPropertyNames()) {
            all.put(key, table.getProperty(key));
        }
        return Collections.unmodifiableSortedMap(all);
    }

    /** The value of the first of {@code keys} that is present (later names are accepted aliases), or null. */
    String string(String... keys) {
        for (String key : keys) {
            if (!this.keys.isKnown(key)) {
                throw new IllegalStateException("property key " + key + " is read but not declared in ServerConfig.KEYS");
            }
            String v = RsProperties.firstWord(table.getProperty(key));
            if (v != null) {
                return v;
            }
        }
        return null;
    }

    boolean bool(boolean fallback, String... keys) throws ConfigException {
        String v = string(keys);
        if (v == null) {
            return fallback;
        }
        String lower = v.toLowerCase(Locale.ROOT);
        if (lower.equals("true")) {
            return true;
        }
        if (lower.equals("false")) {
            return false;
        }
        throw error(keys[0], v, "true or false expected");
    }

    int integer(String key, int fallback, int min, int max) throws ConfigException {
        String v = string(key);
        if (v == null) {
            return fallback;
        }
        int n;
        try {
            n = Integer.parseInt(v);
        } catch (NumberFormatException e) {
            throw error(key, v, "an integer expected");
        }
        if (n < min || n > max) {
            throw error(key, v, "must be in [" + min + ", " + max + "]");
        }
        return n;
    }

    double real(String key, double fallback, double min, double max) throws ConfigException {
        String v = string(key);
        if (v == null) {
            return fallback;
        }
        double d;
        try {
            d = Double.parseDouble(v);
        } catch (NumberFormatException e) {
            throw error(key, v, "a number expected");
        }
        if (!(d >= min && d <= max)) {
            throw error(key, v, "must be in [" + min + ", " + max + "]");
        }
        return d;
    }

    long longValue(String key, long fallback) throws ConfigException {
        String v = string(key);
        if (v == null) {
            return fallback;
        }
        try {
            return Long.parseLong(v);
        } catch (NumberFormatException e) {
            throw error(key, v, "an integer expected");
        }
    }

    /** One of {@code choices} (exactly as written), or {@code fallback} if the key is absent. */
    String choice(String key, String fallback, String... choices) throws ConfigException {
        String v = string(key);
        if (v == null) {
            return fallback;
        }
        for (String c : choices) {
            if (c.equals(v)) {
                return v;
            }
        }
        throw error(key, v, "one of " + String.join(", ", choices) + " expected");
    }

    /** Whether a value is empty (nothing but white space): RP1 0.60 read that as the default, silently. */
    static boolean isEmpty(String value) {
        return RsProperties.firstWord(value) == null;
    }

    ConfigException error(String key, String value, String problem) {
        return new ConfigException(source + ": " + key + "=" + value + ": " + problem);
    }
}
