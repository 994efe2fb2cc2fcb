package rp1.rossum;

import java.io.IOException;
import java.util.Objects;

import rp1.rossum.wire.MessageScanner;
import rp1.rossum.wire.TruncatedMessageException;
import rp1.rossum.wire.WireIn;
import rp1.rossum.wire.WireLimits;

/**
 * Frames for a connection in feed mode ({@link RsConnection#receive}): cuts the bytes a non-blocking
 * reader hands over into whole messages and has each read once it is whole. Where an incomplete
 * message would end is worked out from the bytes as they arrive, each byte once
 * ({@link MessageScanner}); only the start of an incomplete message is kept between calls. Socket-free.
 */
final class FeedDecoder {
    /** Reads one whole message. */
    interface Messages {
        void read(WireIn in) throws IOException;

        /** Whether the handshake is done (before it only CONNECT may come). */
        boolean introduced();
    }

    private static final byte[] NO_BYTES = new byte[0];

    private final Messages messages;
    /** Bytes handed over that do not yet make a whole message. */
    private final FeedBuffer feed = new FeedBuffer();
    /** How far the message at the start of {@link #feed} has been scanned for its end. */
    private final MessageScanner scanner = new MessageScanner();

    FeedDecoder(Messages messages) {
        this.messages = messages;
    }

    /**
     * Reads every whole message among the bytes received so far; an incomplete one waits for the next
     * call. A message counts as consumed even if reading it throws; the messages after it wait.
     *
     * @throws IOException if the bytes break the protocol, or a message grows beyond any the protocol
     *                     allows
     */
    void receive(byte[] bytes, int offset, int length) throws IOException {
        Objects.checkFromIndexSize(offset, length, bytes.length);
        boolean inPlace = feed.length == 0;
        byte[] buffer;
        int at;
        int end;
        if (inPlace) {
            buffer = bytes;
            at = offset;
            end = offset + length;
        } else {
            feed.append(bytes, offset, length);
            buffer = feed.bytes;
            at = 0;
            end = feed.length;
        }
        int start = at;
        try {
            while (at < end) {
                int size = scanner.scan(buffer, at, end, messages.introduced());
                if (size < 0) {
                    if (end - at > WireLimits.MAX_MESSAGE_BYTES) {
                        throw new RsProtocolException(truncation(buffer, at, end).getField(),
                                "message longer than " + WireLimits.MAX_MESSAGE_BYTES + " bytes");
                    }
                    break;
                }
                int from = at;
                at += size;
                messages.read(WireIn.of(buffer, from, size));
            }
        } finally {
            if (inPlace) {
                feed.append(buffer, at, end - at);
            } else {
                feed.consume(at - start);
            }
        }
    }

    /** The bytes of a message that has begun to arrive but is not yet complete (0 between messages). */
    int incompleteBytes() {
        return feed.length;
    }

    /**
     * The input has ended: reads the whole messages still waiting (reading one threw before they were
     * reached), then says what is wrong with what is left.
     *
     * @return null if the input ended between messages, else where the last message breaks off
     * @throws IOException if the waiting bytes break the protocol
     */
    String end() throws IOException {
        receive(NO_BYTES, 0, 0);
        return feed.length > 0 ? truncation(feed.bytes, 0, feed.length).getMessage() : null;
    }

    /**
     * Where the incomplete message in {@code b[at..end)} breaks off: reading it as far as it goes
     * names the field. If those bytes already break the protocol, that is thrown instead.
     */
    private TruncatedMessageException truncation(byte[] b, int at, int end) throws IOException {
        try {
            messages.read(WireIn.of(b, at, end - at));
        } catch (TruncatedMessageException e) {
            return e;
        }
        throw new IllegalStateException("an incomplete message of " + (end - at) + " bytes decoded whole");
    }
}
