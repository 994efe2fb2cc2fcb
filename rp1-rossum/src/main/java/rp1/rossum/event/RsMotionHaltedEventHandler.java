package rp1.rossum.event;

/**
 * Receives motion halted events. Register one with the matching {@code RsClient.add...EventHandler}
 * method; {@link #process} runs on the thread executing {@code RsClient.run()}.
 */
public interface RsMotionHaltedEventHandler extends RsEventHandler {
    /** Handles one event; call {@code event.consume()} to keep later handlers from seeing it. */
    void process(RsMotionHaltedEvent event);
}
