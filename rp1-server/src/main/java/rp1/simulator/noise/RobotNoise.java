package rp1.simulator.noise;

import rp1.rossum.RsBodySensor;
import rp1.rossum.RsTransform;
import rp1.rossum.event.RsEncoderStatusEvent;
import rp1.rossum.event.RsMotionHaltedEvent;
import rp1.rossum.event.RsMotionStartedEvent;
import rp1.rossum.event.RsSensorEvent;
import rp1.rossum.request.RsMotionRequest;

/**
 * Where one robot's truth and what its client is told part ways (docs/behavior.md, "Noise"). The world
 * passes through here the motion it is about to make and each event that reports a reading or a pose;
 * everything else (the robot's pose in the world, snapshots, position reports) stays the truth.
 * {@link #NONE} passes everything through unchanged and draws nothing: RP1 0.60's behaviour.
 *
 * <p>Used only by the thread running the simulation's tasks, in the order of the simulation's events,
 * which is what makes its draws reproducible.
 */
public final class RobotNoise {
    /** No noise. */
    public static final RobotNoise NONE = new RobotNoise(null, null, null);

    private final SensorNoise sensors;
    private final EncoderNoise encoders;
    private final MotionNoise motion;

    RobotNoise(SensorNoise sensors, EncoderNoise encoders, MotionNoise motion) {
        this.sensors = sensors;
        this.encoders = encoders;
        this.motion = motion;
    }

    /**
     * The reading of {@code sensor} at {@code time} that its client gets. {@code changed}: the sensor's
     * true reading has just changed (an event is due), so a new error is drawn; else the last one holds.
     */
    public RsSensorEvent reading(RsBodySensor sensor, double time, boolean changed) {
        return sensors == null ? sensor.getSensorEvent(time) : sensors.reading(sensor, time, changed);
    }

    /** The encoder report the client gets for the true one. */
    public RsEncoderStatusEvent encoder(RsEncoderStatusEvent truth) {
        return encoders == null ? truth : encoders.report(truth);
    }

    /** The robot was placed at this pose: what it believes is the truth again. */
    public void placed(double time, double x, double y, double orientation) {
        if (motion != null) {
            motion.placed(time, x, y, orientation);
        }
    }

    /** The motion the robot really makes for {@code commanded} (a new draw each call). */
    public RsMotionRequest slip(RsMotionRequest commanded) {
        return motion == null ? commanded : motion.slip(commanded);
    }

    /** The robot starts the motion it was commanded, {@code commanded}, at {@code time}. */
    public void begin(double time, RsMotionRequest commanded) {
        if (motion != null) {
            motion.begin(time, commanded);
        }
    }

    /** The motion-started event the client gets for the true one. */
    public RsMotionStartedEvent started(RsMotionStartedEvent truth) {
        return motion == null ? truth : motion.started(truth);
    }

    /** The motion-halted event the client gets for the true one. */
    public RsMotionHaltedEvent halted(RsMotionHaltedEvent truth) {
        return motion == null ? truth : motion.halted(truth);
    }

    /** The pose the robot believes it has at {@code time}, or null when its motion is exact. */
    public RsTransform believedPose(double time) {
        return motion == null ? null : motion.believedPose(time);
    }
}
