package rp1.bench;

import java.io.IOException;
import java.util.Locale;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

import rp1.simulator.launch.RunningServer;

/**
 * Whether {@code simulationSpeed} is what the simulation does: one robot over loopback TCP with a
 * 0.1 s heartbeat and the interlock on, at speeds 10, 100, 1000 and max (the machine's limit for this
 * client), in simulated seconds per wall second.
 */
final class Pacing {
    private static final double MEASURE_SECONDS = 3.0;

    private Pacing() {
    }

    static void run() throws Exception {
        for (String speed : new String[] {"10", "100", "1000", "max"}) {
            RunningServer server = BenchServer.start("simulationSpeed=" + speed, "interlockEnabled=true");
            NetRobot robot = null;
            try {
                robot = placedRobot(server.getPort());
                Thread.sleep(300);
                double s0 = server.getSimulation().getSimTime();
                long t0 = System.nanoTime();
                Thread.sleep((long) (MEASURE_SECONDS * 1000));
                double rate = (server.getSimulation().getSimTime() - s0) / ((System.nanoTime() - t0) * 1e-9);
                String asked = speed.equals("max") ? "as fast as it goes" : String.format(Locale.ROOT, "%.0f%% of %s",
                        100.0 * rate / Double.parseDouble(speed), speed);
                System.out.printf(Locale.ROOT, "simulationSpeed=%-4s one TCP robot, 0.1 s heartbeat, interlock: "
                        + "%,9.1f simulated s per wall s (%s)%n", speed, rate, asked);
            } finally {
                if (robot != null) {
                    robot.leave();
                }
                server.stop();
            }
        }
    }

    private static NetRobot placedRobot(int port) throws IOException, InterruptedException {
        NetRobot c = new NetRobot(port, "paced", 0.1, new CountDownLatch(1));
        c.addHeartbeatEventHandler(e -> { });
        c.sendHeartbeatRequest(0.1);
        c.place("home");
        if (!c.placed().await(10, TimeUnit.SECONDS)) {
            throw new IOException("the robot was not placed within 10 s");
        }
        return c;
    }
}
