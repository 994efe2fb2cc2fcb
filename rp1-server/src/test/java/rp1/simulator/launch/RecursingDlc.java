package rp1.simulator.launch;

/**
 * A loaded client, called directly, whose heartbeat handler at the third beat recurses without end
 * (a robot's bug) or, if asked, throws an InternalError (a failure of the JVM itself, not the robot's).
 */
public class RecursingDlc extends ThirdBeatDlc {
    /** Whether the third beat fails the JVM instead of running out of stack. */
    static volatile boolean internalError;

    public RecursingDlc() {
        super("recursing", "p2");
    }

    @Override
    void thirdBeat() {
        if (internalError) {
            throw new InternalError("made up by the test");
        }
        deeper(0);
    }

    private static int deeper(int n) {
        return deeper(n + 1) + 1;
    }
}
