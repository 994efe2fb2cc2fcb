package rp1.simulator.snapshot;

import java.awt.Color;
import java.nio.file.Paths;

import rp1.planparser.RsPlanParser;
import rp1.rossum.RsBody;
import rp1.rossum.RsBodyCircle;
import rp1.rossum.RsBodyPainter;
import rp1.rossum.RsDifferentialSteering;
import rp1.rossum.RsPlan;
import rp1.rossum.request.RsMotionRequest;
import rp1.rossum.request.RsPainterChangeRequest;
import rp1.simulator.world.EventSink;
import rp1.simulator.world.EventSinks;
import rp1.simulator.world.Robot;
import rp1.simulator.world.World;

/** A WhiteRoom with a painting round robot, driven through the world's own methods. */
final class SnapshotWorlds {
    /** Takes no notice of events. */
    static final EventSink IGNORE = EventSinks.NOWHERE;

    private SnapshotWorlds() {
    }

    static RsPlan whiteRoom() throws Exception {
        return RsPlanParser.parseFile(Paths.get(System.getProperty("rp1.root", ".")).resolve("FloorPlans/WhiteRoom.txt"));
    }

    /** Chassis, painter, then a differential drive with its two default wheels. */
    static RsBody paintingRobot() {
        RsBody body = new RsBody("painter");
        body.addPart(new RsBodyCircle(0.0, 0.0, 0.15));
        body.addPart(new RsBodyPainter(new double[] {-0.01, -0.01, 0.01, -0.01, 0.01, 0.01, -0.01, 0.01}, 4));
        RsDifferentialSteering drive = new RsDifferentialSteering(0.18, 0.075);
        drive.addDefaultWheels(0.075, 0.03);
        body.addPart(drive);
        return body;
    }

    /** Places {@code r} at home, starts its painter, and drives it {@code metres} forward at 0.5 m/s. */
    static void paintForward(World world, Robot r, double metres, double time) {
        if (!r.isPlaced()) {
            world.place(r, "home", time);
        }
        RsBodyPainter painter = r.getBody().getBodyPainterArray()[0];
        world.painterChange(r, new RsPainterChangeRequest(painter.getID(), false, true, true, 0.0, 0.0, 0.02,
                new Color[] {Color.magenta}));
        world.requestMotion(r, new RsMotionRequest(0.5, 0.0, metres / 0.5), time);
    }
}
