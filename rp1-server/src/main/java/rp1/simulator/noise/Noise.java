package rp1.simulator.noise;

/**
 * A run's noise: its settings and the seed every robot's streams of draws are derived from
 * ({@link Draws}). One per simulation; {@link #forRobot} gives each robot its own.
 */
public final class Noise {
    /** No noise: every robot gets {@link RobotNoise#NONE}. */
    public static final Noise OFF = new Noise(NoiseSettings.OFF, 0L);

    private final NoiseSettings settings;
    private final long seed;

    /** The noise of a run with these settings, drawn from streams derived from {@code seed}. */
    public Noise(NoiseSettings settings, long seed) {
        this.settings = settings;
        this.seed = seed;
    }

    public NoiseSettings settings() {
        return settings;
    }

    /** The noise of the robot that joined {@code number}th; {@link RobotNoise#NONE} when noise is off. */
    public RobotNoise forRobot(int number) {
        if (settings.isOff()) {
            return RobotNoise.NONE;
        }
        return new RobotNoise(
                settings.sensorsNoisy() ? new SensorNoise(settings, seed, number) : null,
                settings.encoderMiss > 0 ? new EncoderNoise(settings, seed, number) : null,
                settings.motionNoisy() ? new MotionNoise(settings, seed, number) : null);
    }
}
