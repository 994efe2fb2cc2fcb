package rp1.rossum;

/**
 * Server side: the interlock that stops the simulation clock while a client handles an event. Every
 * event sent opens it with a new, larger number; the client's acknowledgement of the newest number
 * closes it.
 */
public interface RsInterlock {
    /** Stops the clock and returns the new interlock number to put in the event. */
    int openInterlock();

    /**
     * A client acknowledged {@code interlock}; restarts the clock if it is the newest number.
     *
     * @return whether the clock was restarted
     */
    boolean closeInterlock(int interlock);

    /** The newest interlock number handed out. */
    int getMaximumInterlockIndex();
}
