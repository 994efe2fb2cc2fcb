package rp1.rossum.event;

/**
 * Receives contact sensor events. Register one with the matching {@code RsClient.add...EventHandler}
 * method; {@link #process} runs on the thread executing {@code RsClient.run()}.
 */
public interface RsContactSensorEventHandler extends RsEventHandler {
    /** Handles one event; call {@code event.consume()} to keep later handlers from seeing it. */
    void process(RsContactSensorEvent event);
}
