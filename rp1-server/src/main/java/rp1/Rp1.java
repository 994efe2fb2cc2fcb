package rp1;

import java.io.PrintStream;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;

import rp1.simulator.config.ConfigException;
import rp1.simulator.config.ServerArguments;
import rp1.simulator.config.Suggestion;
import rp1.simulator.launch.ExitStatus;
import rp1.simulator.launch.ServerMain;

/**
 * The {@code rp1} command of the installed simulator ({@code bin/rp1}, {@code ./rp1} in the
 * repository, {@code java -jar rp1-server-VERSION.jar}): the simulator, or {@code rp1 replay} and
 * {@code rp1 sweep} (on Apache Spark with {@code --master}, and {@code rp1 cluster}: {@link SparkCommand}).
 * Every file named is relative to the working directory.
 *
 * <p>Without {@code -p} the simulator runs a demo: ClientZero in a window
 * ({@code Properties/RP1.ini}), or, with no display to open one on ({@code --headless},
 * {@code RP1_HEADLESS=1}, no {@code DISPLAY}, or one that does not answer), the fire-fighting robot
 * headless ({@code Properties/headless.ini}). With {@code -p} the file given runs, in a window if
 * it asks for one and there is a display, headless otherwise.
 */
public final class Rp1 {
    /** The commands besides the simulator itself. */
    private static final List<String> COMMANDS = List.of("sweep", "replay", "cluster");

    /** The properties of the headless demo. */
    static final String HEADLESS_DEMO = "headless.ini";

    static final String USAGE = String.join("\n",
            "usage: rp1 [-p PROPERTIES] [-f FLOORPLAN] [--port N] [--headless] [-cp PATH]",
            "       rp1 replay RECORDING [--events OUT] [--snapshot OUT.png] [--html OUT.html] [--until T]",
            "       rp1 sweep -p PROPERTIES --seeds SEEDS --out DIR [--vary KEY=VALUES ...] [--plans A,B] [--jobs N]",
            "                 [--timeout S] [--isolation loader|process] [--client CMD] [--pictures] [--resume]",
            "                 [--html] [-cp PATH] [--master local[N]|spark://HOST:PORT [--keep NAMES]]",
            "       rp1 cluster [--workers N]      a Spark cluster on this machine, for rp1 sweep --master",
            "Without -p: a demo robot, in a window (Properties/RP1.ini), or without a display headless",
            "(Properties/headless.ini, its picture in firefighter.png). rp1 replay -h and rp1 sweep -h say more.",
            "",
            ServerArguments.USAGE.replace("usage: java rp1.Server", "rp1"));

    private Rp1() {
    }

    /** Runs the command; the process exits with its status. */
    public static void main(String[] args) {
        String[] rest = args.length > 0 ? Arrays.copyOfRange(args, 1, args.length) : args;
        if (args.length > 0 && args[0].equals("sweep") && SparkCommand.wanted(rest)) {
            System.exit(SparkCommand.run(SparkCommand.SWEEP, rest, System.err));
        } else if (args.length > 0 && args[0].equals("cluster")) {
            System.exit(SparkCommand.run(SparkCommand.CLUSTER, rest, System.err));
        } else if (args.length > 0 && args[0].equals("sweep")) {
            Sweep.main("rp1 sweep", rest);
        } else if (args.length > 0 && args[0].equals("replay")) {
            Replay.main("rp1 replay", rest);
        } else if (args.length > 0 && misspeltCommand(args[0]) != null) {
            System.err.println(misspeltCommand(args[0]));
            System.exit(ExitStatus.STARTUP_FAILED);
        } else {
            System.exit(server(args, System.getenv(), System.err));
        }
    }

    /**
     * For a word that is a slip of a command's name, what to tell the user ("rp1: unknown command swep;
     * did you mean rp1 sweep?" and the usage); else null. Without it the simulator would take the word
     * for a stray argument of its own.
     */
    static String misspeltCommand(String word) {
        String meant = Suggestion.nearest(word, COMMANDS);
        return meant == null ? null : "rp1: unknown command " + word + "; did you mean rp1 " + meant + "?\n" + USAGE;
    }

    /** Runs the simulator as {@link #serverArguments} says; returns the exit status. */
    static int server(String[] args, Map<String, String> environment, PrintStream err) {
        String[] serverArgs;
        try {
            if (ServerArguments.parse(args).help) {
                System.out.println(USAGE);
                return ExitStatus.OK;
            }
            serverArgs = serverArguments(args, environment, err);
        } catch (ConfigException e) {
            err.println("rp1: " + e.getMessage().replace("usage: java rp1.Server", "usage: rp1"));
            return ExitStatus.STARTUP_FAILED;
        }
        return ServerMain.run(serverArgs);
    }

    /**
     * The server's command line: the one given, made headless when there is no display to draw on,
     * and without {@code -p} the demo that suits the display.
     */
    static String[] serverArguments(String[] args, Map<String, String> environment, PrintStream err)
            throws ConfigException {
        ServerArguments given = ServerArguments.parse(args);
        boolean headless = given.headless || "1".equals(environment.get("RP1_HEADLESS"))
                || !Display.answers(environment.get("DISPLAY"));
        List<String> result = new ArrayList<>(Arrays.asList(args));
        if (headless && !given.headless) {
            result.add("--headless");
        }
        if (given.propertiesName == null && headless) {
            err.println("rp1: no display: the fire-fighting robot runs without a window (Properties/" + HEADLESS_DEMO
                    + "); its picture goes to firefighter.png");
            result.addAll(List.of("-p", HEADLESS_DEMO));
        }
        return result.toArray(new String[0]);
    }
}
