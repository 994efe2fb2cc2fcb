package rp1.rossum.request;

import java.util.ArrayList;
import java.util.Locale;

/**
 * A command for an actuator (a wheel system) with named parameters, e.g. the wheel rotational
 * velocities of a differential drive. The simulator uses the parameter values by position; the names
 * document them. Usually built by {@code RsDifferentialSteering.getControlRequestForWheelRotation} or
 * {@code RsAckermanSteering.getControlRequestForWheelRotationAndSteeringAngle}.
 */
public class RsActuatorControlRequest extends RsRequest {
    private static final long serialVersionUID = 1L;

    /**
     * {@link #commandID}: stop. Without parameters the client library sends a halt request instead
     * (docs/differences.md).
     */
    public static final int HALT = 1;
    /** {@link #commandID}: reset. The simulator reads only the parameter values (behavior.md section 5.5). */
    public static final int RESET = 2;
    /**
     * {@link #commandID}: drive the actuator with the parameter values (behavior.md section 5.5).
     */
    public static final int ACTIVATE = 3;

    /** Part id of the actuator (wheel system). */
    public final int actuatorID;
    /** {@link #HALT}, {@link #RESET} or {@link #ACTIVATE}. */
    public final int commandID;
    /** The named parameters, in the order the simulator reads their values. */
    protected ArrayList<ParameterPair> parameterList = new ArrayList<>();

    /**
     * A command without parameters yet: add them in the order the actuator reads them.
     *
     * @param actuatorID part id of the actuator (wheel system)
     * @param commandID {@link #HALT}, {@link #RESET} or {@link #ACTIVATE}
     */
    public RsActuatorControlRequest(int actuatorID, int commandID) {
        super(REQ_ACTUATOR_CONTROL);
        this.actuatorID = actuatorID;
        this.commandID = commandID;
    }

    /** Appends a parameter; order matters to the simulator. */
    public void addParameter(String name, double value) {
        parameterList.add(new ParameterPair(name, value));
    }

    /** Whether a parameter of this name (ignoring case) was added. */
    public boolean isParameterDefined(String name) {
        return find(name) != null;
    }

    /** The value of the first parameter with this name (ignoring case), 0.0 if there is none. */
    public double getParameterByName(String name) {
        ParameterPair p = find(name);
        return p == null ? 0.0 : p.value;
    }

    private ParameterPair find(String name) {
        if (name == null) {
            return null;
        }
        String key = name.toLowerCase(Locale.ROOT);
        for (ParameterPair p : parameterList) {
            if (p.name != null && p.name.toLowerCase(Locale.ROOT).equals(key)) {
                return p;
            }
        }
        return null;
    }

    /** Parameter names in the order they were added. */
    public String[] getParameterNames() {
        String[] names = new String[parameterList.size()];
        for (int i = 0; i < names.length; i++) {
            names[i] = parameterList.get(i).name;
        }
        return names;
    }

    /** Parameter values in the order they were added. */
    public double[] getParameterValues() {
        double[] values = new double[parameterList.size()];
        for (int i = 0; i < values.length; i++) {
            values[i] = parameterList.get(i).value;
        }
        return values;
    }

    /** The actuator's part id (same as {@link #actuatorID}). */
    public int getBodyPartID() {
        return actuatorID;
    }

    @Override
    public String toString() {
        StringBuilder b = new StringBuilder("RsActuatorControlRequest[actuator=").append(actuatorID)
                .append(", command=").append(commandID);
        for (ParameterPair p : parameterList) {
            b.append(", ").append(p.name).append('=').append(p.value);
        }
        return b.append(']').toString();
    }

    private static final class ParameterPair implements java.io.Serializable {
        private static final long serialVersionUID = 1L;
        final String name;
        final double value;

        ParameterPair(String name, double value) {
            this.name = name;
            this.value = value;
        }
    }
}
