package rp1.rossum.event;

/**
 * Receives placement events. Register one with the matching {@code RsClient.add...EventHandler}
 * method; {@link #process} runs on the thread executing {@code RsClient.run()}.
 */
public interface RsPlacementEventHandler extends RsEventHandler {
    /** Handles one event; call {@code event.consume()} to keep later handlers from seeing it. */
    void process(RsPlacementEvent event);
}
