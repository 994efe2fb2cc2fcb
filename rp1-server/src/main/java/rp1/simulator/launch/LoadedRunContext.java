package rp1.simulator.launch;

import java.util.Map;

import rp1.rossum.RsRunContext;
import rp1.simulator.AskedParameters;
import rp1.simulator.ReportedResults;

/**
 * The run as the server hands it to a client it loads: the properties' {@code param.NAME} values (the
 * names asked for are noted, for a sweep to check), the simulation's seed, and its results, recorded
 * under the client's session number so that they end up on its robot's row. A client that connects
 * itself over TCP ({@code dlcSetIO=false}) has no session yet when it is loaded: it gets the
 * parameters and the seed, and its results are not kept.
 */
final class LoadedRunContext implements RsRunContext {
    /** The session number of a client whose results are not kept. */
    static final int NO_SESSION = 0;

    private final Map<String, String> parameters;
    private final AskedParameters asked;
    private final long seed;
    private final ReportedResults results;
    private final int session;

    LoadedRunContext(Map<String, String> parameters, AskedParameters asked, long seed, ReportedResults results,
                     int session) {
        this.parameters = Map.copyOf(parameters);
        this.asked = asked;
        this.seed = seed;
        this.results = results;
        this.session = session;
    }

    @Override
    public String getParameter(String name) {
        asked.asked(name);
        return parameters.get(name);
    }

    @Override
    public long getSeed() {
        return seed;
    }

    @Override
    public void reportResult(String name, double value) {
        if (session != NO_SESSION) {
            results.report(session, name, value);
        }
    }
}
