package rp1.simulator.launch;

/**
 * A loaded client, called directly, whose heartbeat handler at the third beat recurses without end
 * (a robot's bug) or, if asked, throws an OutOfMemoryError.
 */
public class RecursingDlc extends ThirdBeatDlc {
    /** Whether the third beat runs out of memory instead of stack. */
    static volatile boolean outOfMemory;

    public RecursingDlc() {
        super("recursing", "p2");
    }

    @Override
    void thirdBeat() {
        if (outOfMemory) {
            throw new OutOfMemoryError("made up by the test");
        }
        deeper(0);
    }

    private static int deeper(int n) {
        return deeper(n + 1) + 1;
    }
}
