package rp1demo.firefighter;

import java.awt.Color;
import java.io.IOException;

import rp1.rossum.RsBodyTargetSensor;
import rp1.rossum.event.RsTargetSensorEvent;
import rp1demo.Standalone;
import rp1demo.adapter.Poses;
import rp1demo.adapter.ScoutClient;
import rp1demo.navigation.NavNetwork;
import rp1demo.navigation.Pose;

/**
 * The fire fighter's connection to the simulator: a ClientZero whose "head" is the candle sensor
 * and which leaves a red trail. Once the floor plan and the "home" placement are in, events go to
 * the {@link FireFighter} and its commands become requests.
 */
public class FfMain extends ScoutClient implements FireFighter.Robot {
    /** Distance from the robot's centre to the candle at which it stops, metres. */
    public static final double STANDOFF = 0.4;
    /** Candles farther than this from where the robot looks around are in another room, metres. */
    public static final double REACH = 1.2;

    private volatile FireFighter fireFighter;

    /**
     * Connects to a simulator on the network and runs until it goes away.
     * If it cannot be reached, says so in one line and exits with status 1.
     */
    public static void main(String[] args) {
        Standalone.run(new FfMain());
    }

    /** The no-argument constructor the simulator uses to load the class. */
    public FfMain() {
        super(Color.red);
    }

    /** The search strategy, once the search has begun (else null). */
    public FireFighter getFireFighter() {
        return fireFighter;
    }

    @Override
    protected void addHandlers() {
        addTargetSensorEventHandler((RsBodyTargetSensor) getBody().getPartByName("head"), this::sighting);
    }

    @Override
    protected void begin(NavNetwork network, Pose pose) {
        fireFighter = new FireFighter(network, STANDOFF, REACH, this, this::log);
        fireFighter.start(pose);
    }

    @Override
    protected void moveEnded(Pose pose) {
        fireFighter.moveEnded(pose);
    }

    @Override
    protected void collided(Pose pose) {
        fireFighter.blocked(pose);
    }

    /** What the head sees goes to the strategy as candle positions in the world. */
    private void sighting(RsTargetSensorEvent e) {
        FireFighter f = fireFighter;
        if (f == null) {
            return;
        }
        if (e.status) {
            double[] at = Poses.targetPosition(e);
            f.candleInSight(e.getNameOfObjectDetected(), at[0], at[1]);
        } else {
            f.candleOutOfSight();
        }
    }

    @Override
    public void stop() {
        sendHaltRequest();
    }

    @Override
    public void finished(boolean success) {
        liftPen();
        log(success ? "Fire fighter: candle found" : "Fire fighter: search over, no candle found");
    }
}
