package rp1.simulator.world;

import rp1.rossum.event.RsEvent;

/** Event sinks for tests that need a robot but not its client. */
public final class EventSinks {
    /** Subscribed to nothing; sends nowhere. */
    public static final EventSink NOWHERE = new EventSink() {
        @Override
        public void send(RsEvent event) {
        }

        @Override
        public boolean isSubscribed(int eventCode, int index) {
            return false;
        }
    };

    private EventSinks() {
    }
}
