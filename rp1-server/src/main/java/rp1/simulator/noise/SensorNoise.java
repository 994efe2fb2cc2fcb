package rp1.simulator.noise;

import java.util.HashMap;
import java.util.Map;

import rp1.rossum.RsBodyRangeSensor;
import rp1.rossum.RsBodySensor;
import rp1.rossum.RsBodyTargetSensor;
import rp1.rossum.event.RsRangeSensorEvent;
import rp1.rossum.event.RsSensorEvent;
import rp1.rossum.event.RsTargetSensorEvent;

/**
 * What one robot's range and target sensors report, given what they truly see. A sensor keeps the
 * error drawn for its latest reading until the reading changes (the moment RP1 sends a sensor event),
 * so a status request reports the same noisy reading as the last event did. The sensor itself keeps
 * the truth, which decides when readings change.
 */
final class SensorNoise {
    private final NoiseSettings settings;
    private final Draws range;
    private final Draws dropout;
    private final Draws targetRange;
    private final Draws bearing;
    /** Per sensor part id, the error of its latest reading. */
    private final Map<Integer, Error> errors = new HashMap<>();

    SensorNoise(NoiseSettings settings, long seed, int robot) {
        this.settings = settings;
        range = new Draws(seed, robot, Draws.Quantity.RANGE);
        dropout = new Draws(seed, robot, Draws.Quantity.DROPOUT);
        targetRange = new Draws(seed, robot, Draws.Quantity.TARGET_RANGE);
        bearing = new Draws(seed, robot, Draws.Quantity.TARGET_BEARING);
    }

    /**
     * The reading of {@code sensor} at {@code time} as the client gets it; {@code fresh}: the reading has
     * just changed, so its error is drawn anew. Other sensors than range and target ones are exact.
     */
    RsSensorEvent reading(RsBodySensor sensor, double time, boolean fresh) {
        RsSensorEvent truth = sensor.getSensorEvent(time);
        if (truth instanceof RsRangeSensorEvent && sensor instanceof RsBodyRangeSensor) {
            return range((RsRangeSensorEvent) truth, ((RsBodyRangeSensor) sensor).getMaxRange(), errorOf(sensor, fresh));
        }
        if (truth instanceof RsTargetSensorEvent && sensor instanceof RsBodyTargetSensor) {
            return target((RsTargetSensorEvent) truth, errorOf(sensor, fresh));
        }
        return truth;
    }

    private Error errorOf(RsBodySensor sensor, boolean fresh) {
        Error e = errors.get(sensor.getID());
        if (fresh || e == null) {
            e = sensor instanceof RsBodyRangeSensor
                    ? new Error(range.gaussian(settings.rangeSigma), 0.0, dropout.chance(settings.rangeDropout))
                    : new Error(targetRange.gaussian(settings.targetRangeSigma),
                            bearing.gaussian(settings.targetBearingSigma), false);
            errors.put(sensor.getID(), e);
        }
        return e;
    }

    /** A detection off by the range error, within [0, maxRange]; a lost reading detects nothing. */
    private static RsSensorEvent range(RsRangeSensorEvent t, double maxRange, Error e) {
        if (!t.status) {
            return t;
        }
        if (e.lost()) {
            return new RsRangeSensorEvent(t.simTime, t.sensorID, t.x, t.y, t.ux, t.uy, false, 0.0, "");
        }
        double r = Math.max(0.0, Math.min(maxRange, t.range + e.range()));
        return new RsRangeSensorEvent(t.simTime, t.sensorID, t.x, t.y, t.ux, t.uy, true, r,
                t.getNameOfObjectDetected());
    }

    /** A detection off in range (not below 0) and bearing (within (-pi, pi]); the offsets agree with both. */
    private static RsSensorEvent target(RsTargetSensorEvent t, Error e) {
        if (!t.status) {
            return t;
        }
        double r = Math.max(0.0, t.range + e.range());
        double b = Math.IEEEremainder(t.bearing + e.bearing(), 2.0 * Math.PI);
        return new RsTargetSensorEvent(t.simTime, t.sensorID, t.x, t.y, t.ux, t.uy, true, r * Math.cos(b),
                r * Math.sin(b), r, b, t.getNameOfObjectDetected());
    }

    /** The error of one reading: added to the range and bearing, or the reading lost. */
    private record Error(double range, double bearing, boolean lost) {
    }
}
