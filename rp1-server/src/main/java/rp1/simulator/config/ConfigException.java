package rp1.simulator.config;

/**
 * The server's configuration is unusable: a properties file or floor plan cannot be found, or a key
 * has an invalid value. The message names the file and, where there is one, the key and the value;
 * the server does not start.
 */
public class ConfigException extends Exception {
    private static final long serialVersionUID = 1L;

    public ConfigException(String message) {
        super(message);
    }

    public ConfigException(String message, Throwable cause) {
        super(message, cause);
    }
}
