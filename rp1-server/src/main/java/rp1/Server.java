package rp1;

import rp1.simulator.launch.ServerMain;

/**
 * The RP1 simulator: {@code java rp1.Server [-p PROPERTIES] [-f FLOORPLAN]}. The properties file is
 * looked for in the working directory, then as {@code Properties/NAME} on the class path (default
 * {@code Properties/RP1.ini}); the floor plan as a path, in {@code FloorPlans/}, then on the class path.
 * Exit status 0 when stopped as asked, 1 if it could not start, 2 if a loaded client failed, 4 if an
 * output could not be written, 70 if the simulator failed, 130 or 143 after Ctrl-C or SIGTERM.
 */
public final class Server {
    private Server() {
    }

    /** Runs the server; the process exits with its status. */
    public static void main(String[] args) {
        System.exit(ServerMain.run(args));
    }
}
