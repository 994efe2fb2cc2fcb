package rp1.simulator.session;

import rp1.rossum.wire.WireLimits;

/**
 * What one client may make the server hold, in bytes (docs/properties.md, docs/protocol.md section
 * 14): events waiting for it to read them, its pending timeouts, its subscriptions, and a message of
 * its that has begun to arrive. A client over any of them is disconnected with a log line naming the
 * budget, so one client cannot exhaust the memory every other client needs.
 *
 * <p>Timeouts and subscriptions are counted at a fixed size each, about what one holds in the server
 * (the request waiting for the next boundary, the task, the entry in the client's table); the other
 * two are counted byte for byte.
 */
public final class ClientBudgets {
    /** Bytes one pending timeout counts. */
    public static final int TIMEOUT_BYTES = 256;
    /** Bytes one subscription counts. */
    public static final int SUBSCRIPTION_BYTES = 128;
    /** The defaults of the properties; a message may take all the protocol allows one to be. */
    public static final ClientBudgets DEFAULTS = new ClientBudgets(8 << 20, 4 << 20, 1 << 20, WireLimits.MAX_MESSAGE_BYTES);

    /** Bytes of events waiting for the client to read them ({@code clientOutputBudget}). */
    public final int output;
    /** Bytes counted for the timeouts the client asked for that have not fallen due ({@code clientTimeoutBudget}). */
    public final int timeouts;
    /** Bytes counted for the client's subscriptions ({@code clientSubscriptionBudget}). */
    public final int subscriptions;
    /** Bytes of a message that has begun to arrive and is not yet whole ({@code clientMessageBudget}). */
    public final int message;

    /**
     * Budgets in bytes, each positive.
     *
     * @throws IllegalArgumentException naming the budget that is not positive
     */
    public ClientBudgets(int output, int timeouts, int subscriptions, int message) {
        this.output = positive("output", output);
        this.timeouts = positive("timeouts", timeouts);
        this.subscriptions = positive("subscriptions", subscriptions);
        this.message = positive("message", message);
    }

    private static int positive(String name, int bytes) {
        if (bytes <= 0) {
            throw new IllegalArgumentException(name + " budget must be positive, got " + bytes);
        }
        return bytes;
    }

    /**
     * Why {@code count} items of {@code itemBytes} each are over {@code budget} bytes, or null if they
     * are not: "N pending timeouts count B bytes, the budget is X (KEY)".
     */
    static String over(int count, String items, int itemBytes, int budget, String key) {
        long bytes = (long) count * itemBytes;
        return bytes <= budget ? null
                : count + " " + items + " count " + bytes + " bytes, the budget is " + budget + " (" + key + ")";
    }
}
