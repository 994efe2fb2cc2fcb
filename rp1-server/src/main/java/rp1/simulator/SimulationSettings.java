package rp1.simulator;

import rp1.simulator.config.ServerConfig;
import rp1.simulator.noise.Noise;
import rp1.simulator.noise.NoiseSettings;
import rp1.simulator.scheduler.SimClock;
import rp1.simulator.scheduler.TimeSource;

/**
 * What a simulation needs to know besides its floor plan: how often motion is evaluated, how its
 * clock runs, whether events interlock with clients, the seed of its one random source, whether
 * robots meet each other, and how noisy sensors and motion are. Immutable.
 */
public final class SimulationSettings {
    /** Seconds between motion evaluations. */
    public final double modelingInterval;
    /** Simulated seconds per wall second; infinite for lockstep. */
    public final double speed;
    public final boolean interlock;
    public final long randomSeed;
    public final TimeSource wallClock;
    /** Whether robots collide with, sense and block the placement of one another (RP1 0.60: no). */
    public final boolean robotsInteract;
    /** A replay of a recorded run: lockstep, and nothing holds its clock ({@link SimClock#replay()}). */
    public final boolean replay;
    /** How noisy sensors and motion are; the draws come from streams derived from {@link #randomSeed}. */
    public final NoiseSettings noise;

    public SimulationSettings(double modelingInterval, double speed, boolean interlock, long randomSeed,
                              TimeSource wallClock) {
        this(modelingInterval, speed, interlock, randomSeed, wallClock, true, false, NoiseSettings.OFF);
    }

    private SimulationSettings(double modelingInterval, double speed, boolean interlock, long randomSeed,
                               TimeSource wallClock, boolean robotsInteract, boolean replay, NoiseSettings noise) {
        if (!(modelingInterval > 0.0)) {
            throw new IllegalArgumentException("modelingInterval must be positive, got " + modelingInterval);
        }
        if (!(speed > 0.0)) {
            throw new IllegalArgumentException("speed must be positive, got " + speed);
        }
        this.modelingInterval = modelingInterval;
        this.speed = speed;
        this.interlock = interlock;
        this.randomSeed = randomSeed;
        this.wallClock = wallClock;
        this.robotsInteract = robotsInteract;
        this.replay = replay;
        this.noise = noise;
    }

    /** The same settings with robots meeting each other or not ({@code robotsInteract}). */
    public SimulationSettings withRobotsInteract(boolean interact) {
        return new SimulationSettings(modelingInterval, speed, interlock, randomSeed, wallClock, interact, replay, noise);
    }

    /** The same settings with this noise ({@link NoiseSettings#OFF}: none, as in RP1 0.60). */
    public SimulationSettings withNoise(NoiseSettings n) {
        return new SimulationSettings(modelingInterval, speed, interlock, randomSeed, wallClock, robotsInteract, replay, n);
    }

    /** The run's noise: its settings, drawn from streams derived from the seed. */
    public Noise newNoise() {
        return new Noise(noise, randomSeed);
    }

    /**
     * Lockstep with the interlock: time jumps from task to task and waits only for clients, so the
     * same plan, seed and client give the same events on every run, as fast as they can be computed.
     */
    public static SimulationSettings lockstep(double modelingInterval, long randomSeed) {
        return new SimulationSettings(modelingInterval, Double.POSITIVE_INFINITY, true, randomSeed, null);
    }

    /** A clock paced by the system's wall clock at {@code speed}. */
    public static SimulationSettings paced(double modelingInterval, double speed, boolean interlock, long randomSeed) {
        return new SimulationSettings(modelingInterval, speed, interlock, randomSeed, TimeSource.SYSTEM);
    }

    /** What a server's properties ask for, with the random source seeded by {@code seed}. */
    public static SimulationSettings of(ServerConfig config, long seed) {
        SimulationSettings s = config.lockstep
                ? lockstep(config.modelingInterval, seed)
                : paced(config.modelingInterval, config.simulationSpeed, config.interlockEnabled, seed);
        return s.withRobotsInteract(config.robotsInteract).withNoise(config.noise);
    }

    /**
     * For replaying a recorded run with these settings' modelling interval, seed, robot interaction and noise:
     * no interlock (there are no clients to wait for), and a clock nothing holds.
     */
    public SimulationSettings forReplay() {
        return new SimulationSettings(modelingInterval, Double.POSITIVE_INFINITY, false, randomSeed, null,
                robotsInteract, true, noise);
    }

    public boolean isLockstep() {
        return Double.isInfinite(speed);
    }

    SimClock newClock() {
        if (replay) {
            return SimClock.replay();
        }
        return isLockstep() ? SimClock.lockstep() : SimClock.paced(wallClock, speed);
    }
}
