package rp1.rossum;

import java.util.Map;

/**
 * What a client learns of the run it is part of, and where it reports results of its own
 * (docs/guide.md, "Experiments"): the run's parameters (the server's {@code param.NAME} properties),
 * its seed, and named results that become columns of a sweep's {@code results.csv}. A server that
 * loads a client gives it one ({@link RsClient#setRunContext}); a client started by a sweep's
 * {@code --client} finds one in its environment ({@link #fromEnvironment(Map)}).
 */
public interface RsRunContext {
    /** The environment variable holding the port of the server a sweep's {@code --client} connects to. */
    String PORT_VARIABLE = "RP1_PORT";
    /** The environment variable holding the run's seed. */
    String SEED_VARIABLE = "RP1_SEED";
    /** The prefix of the environment variables holding the run's parameters: {@code RP1_PARAM_NAME}. */
    String PARAMETER_PREFIX = "RP1_PARAM_";
    /** The environment variable naming the file results are appended to, a line {@code NAME VALUE} each. */
    String RESULTS_VARIABLE = "RP1_RESULTS";

    /**
     * The value of the run's parameter {@code name} ({@code param.NAME} in the server's properties).
     *
     * @param name the parameter's name, without {@code param.}
     * @return its value, or null if the run has none of that name
     */
    String getParameter(String name);

    /**
     * The run's seed (the server's {@code randomSeed}, or the one it chose).
     *
     * @return the seed, or 0 if unknown
     */
    long getSeed();

    /**
     * Reports a result of the client's own; the last value reported for a name wins.
     *
     * @param name  the result's name, checked by the caller ({@link RsClient#reportRunResult})
     * @param value the value, a finite number
     */
    void reportResult(String name, double value);

    /**
     * A context read from environment variables, as a sweep's {@code --client} sets them:
     * {@link #SEED_VARIABLE}, {@code RP1_PARAM_NAME} for each parameter (characters of NAME other than
     * letters, digits and {@code _} written as {@code _}) and {@link #RESULTS_VARIABLE}. Without them,
     * no parameters, seed 0, and reported results are dropped.
     *
     * @param environment the variables, usually {@code System.getenv()}
     * @return the context
     */
    static RsRunContext fromEnvironment(Map<String, String> environment) {
        return new EnvironmentRunContext(environment);
    }

    /**
     * The environment variable that holds parameter {@code name}: {@code RP1_PARAM_} and the name with
     * every character other than a letter, a digit or {@code _} replaced by {@code _}.
     *
     * @param name the parameter's name, without {@code param.}
     * @return the variable's name
     */
    static String parameterVariable(String name) {
        return PARAMETER_PREFIX + name.replaceAll("[^A-Za-z0-9_]", "_");
    }
}
