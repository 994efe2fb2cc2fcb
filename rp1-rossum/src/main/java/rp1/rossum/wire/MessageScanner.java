package rp1.rossum.wire;

import java.util.ArrayDeque;

import rp1.rossum.request.RsRequest;

/**
 * Finds where a message a client sends ends, a few bytes at a time, without building anything: a
 * non-blocking reader hands it each arrival and it picks up where the previous one left off, so a
 * message that trickles in is passed over once in all, not once per arrival. The message is then
 * decoded once, whole, by the codecs.
 *
 * <p>The scanner knows the layout of what a server receives (CONNECT, REQUEST, BODY_SPECIFICATION,
 * INTERLOCK; protocol.md sections 3, 6 and 8) and reads only the values the layout depends on: codes,
 * counts, flags and string lengths. When one of those is a value the decoder refuses (an unknown code,
 * a count out of range, a colour component outside 0..255), the message ends there, so that decoding
 * it reports the error at once instead of waiting for bytes that may never come.
 *
 * <p>Socket-free: {@link #scan} works on any byte array.
 */
public final class MessageScanner {
    /** What a value read from the wire decides about what follows it. */
    @FunctionalInterface
    private interface Then {
        void with(int value);
    }

    /** Pass over {@code skip} bytes, or read a {@code width}-byte value and hand it to {@code then}. */
    private static final class Step {
        final int width;
        long skip;
        final Then then;

        Step(int width, long skip, Then then) {
            this.width = width;
            this.skip = skip;
            this.then = then;
        }
    }

    private static final Then NOTHING = v -> { };
    private static final int I32 = 4;
    private static final int U16 = 2;
    private static final int BOOL = 1;
    private static final int F64 = 8;

    private final ArrayDeque<Step> steps = new ArrayDeque<>();
    private boolean started;
    /** Bytes of the current message already passed over. */
    private int scanned;

    /**
     * Scans on in the message that starts at {@code start}, whose bytes so far end at {@code end}.
     * The bytes before {@code start + }{@link #scanned()} must be those of the previous call.
     *
     * @param introduced whether the handshake is done (before it only CONNECT may come)
     * @return the message's length once it is whole (the scanner is then ready for the next one), or
     *         -1 while bytes are missing
     */
    public int scan(byte[] bytes, int start, int end, boolean introduced) {
        if (!started) {
            started = true;
            read(I32, version -> {
                if (version != WireCodes.VERSION) {
                    end();
                }
            });
            skip(3 * I32);
            read(I32, introduced ? this::transaction : NOTHING);
        }
        int at = start + scanned;
        while (!steps.isEmpty()) {
            Step s = steps.peekFirst();
            if (s.skip > 0) {
                long taken = Math.min(s.skip, end - at);
                at += (int) taken;
                s.skip -= taken;
                if (s.skip > 0) {
                    break;
                }
                steps.removeFirst();
            } else if (end - at >= s.width) {
                steps.removeFirst();
                int value = value(bytes, at, s.width);
                at += s.width;
                s.then.with(value);
            } else {
                break;
            }
        }
        scanned = at - start;
        if (!steps.isEmpty()) {
            return -1;
        }
        int length = scanned;
        started = false;
        scanned = 0;
        return length;
    }

    /** Bytes of an unfinished message already scanned (0 between messages). */
    public int scanned() {
        return scanned;
    }

    private static int value(byte[] b, int at, int width) {
        int v = 0;
        for (int i = 0; i < width; i++) {
            v = (v << 8) | (b[at + i] & 0xFF);
        }
        return v;
    }

    // The layout. Each method adds its steps after those already waiting in the current group: a
    // Then runs with its own steps gone and adds the ones it decides on in front of the rest.

    private ArrayDeque<Step> group;

    /** Runs {@code layout} so that the steps it adds come before every step still waiting. */
    private void first(Runnable layout) {
        ArrayDeque<Step> outer = group;
        group = new ArrayDeque<>();
        layout.run();
        while (!group.isEmpty()) {
            steps.addFirst(group.removeLast());
        }
        group = outer;
    }

    private void add(Step s) {
        if (group != null) {
            group.addLast(s);
        } else {
            steps.addLast(s);
        }
    }

    private void skip(long bytes) {
        if (bytes > 0) {
            add(new Step(0, bytes, NOTHING));
        }
    }

    private void read(int width, Then then) {
        add(new Step(width, 0, v -> first(() -> then.with(v))));
    }

    /** The message ends here: decoding it reports what is wrong with the value just read. */
    private void end() {
        steps.clear();
        if (group != null) {
            group.clear();
        }
    }

    private void str() {
        read(U16, this::skip);
    }

    /** {@code n} items laid out by {@code item}, one after the other. */
    private void times(int n, Runnable item) {
        if (n > 0) {
            add(new Step(0, 0, v -> first(() -> {
                item.run();
                times(n - 1, item);
            })));
        }
    }

    /** A count in 0..max, then what {@code items} lays out for it; a count outside ends the message. */
    private void count(int max, Then items) {
        read(I32, n -> {
            if (n < 0 || n > max) {
                end();
            } else {
                items.with(n);
            }
        });
    }

    private void transaction(int code) {
        switch (code) {
            case WireCodes.REQUEST:
                read(I32, this::request);
                break;
            case WireCodes.BODY_SPECIFICATION:
                body();
                break;
            case WireCodes.INTERLOCK:
                skip(I32);
                break;
            default:
                end();
        }
    }

    private void request(int code) {
        if (code < 0 || code > RsRequest.REQ_MAX_CODE) {
            end();
            return;
        }
        skip(I32);
        switch (code) {
            case RsRequest.REQ_TIMEOUT:
                skip(F64 + I32);
                break;
            case RsRequest.REQ_SUBSCRIPTION:
                skip(2 * I32 + BOOL);
                break;
            case RsRequest.REQ_SENSOR_STATUS:
                skip(I32);
                break;
            case RsRequest.REQ_MOTION:
                skip(3 * F64);
                break;
            case RsRequest.REQ_PLACEMENT:
                read(I32, named -> {
                    if (named != 0) {
                        str();
                    }
                });
                break;
            case RsRequest.REQ_TARGET_SELECTION:
                skip(BOOL);
                str();
                skip(2 * BOOL);
                break;
            case RsRequest.REQ_HEARTBEAT:
                skip(F64);
                break;
            case RsRequest.REQ_PAINTER_CHANGE:
                painterChange();
                break;
            case RsRequest.REQ_ACTUATOR_CONTROL:
                skip(2 * I32);
                count(WireLimits.MAX_ACTUATOR_PARAMETERS, n -> times(n, () -> {
                    str();
                    skip(F64);
                }));
                break;
            case RsRequest.REQ_ENCODER_STATUS:
                skip(I32);
                count(WireLimits.MAX_ENCODERS, n -> skip((long) n * I32));
                skip(BOOL);
                break;
            default:
                break;
        }
    }

    private void painterChange() {
        skip(I32);
        read(BOOL, erasure -> {
            if (erasure == 0) {
                read(BOOL, activation -> {
                    if (activation != 0) {
                        skip(BOOL + 3 * F64);
                        count(WireLimits.MAX_COLORS, n -> times(n, this::color));
                    }
                });
            }
        });
    }

    private void color() {
        read(I32, present -> {
            if (present != 0) {
                times(3, () -> read(I32, c -> {
                    if (c < 0 || c > 255) {
                        end();
                    }
                }));
            }
        });
    }

    private void body() {
        str();
        count(WireLimits.MAX_BODY_PARTS, n -> times(n, this::part));
    }

    private void part() {
        read(I32, id -> {
            if (id != WireCodes.EMPTY_SLOT) {
                read(I32, type -> {
                    if (type != WireCodes.UNDEFINED_BODY_PART) {
                        partOfType(type);
                    }
                });
            }
        });
    }

    private void partOfType(int type) {
        switch (type) {
            case WireCodes.WHEEL_SYSTEM:
                read(I32, system -> skip(system == WireCodes.DIFFERENTIAL ? 2 * F64 : 4 * F64 + BOOL));
                count(WireLimits.MAX_WHEELS, n -> times(n, () -> {
                    skip(I32);
                    outline();
                    skip(4 * F64 + I32);
                }));
                break;
            case WireCodes.BODY_CIRCLE:
                skip(3 * F64);
                break;
            case WireCodes.BODY_SHAPE:
            case WireCodes.BODY_CONTACT_SENSOR:
            case WireCodes.BODY_PAINTER:
                outline();
                break;
            case WireCodes.BODY_TARGET_SENSOR:
                outline();
                skip(5 * F64 + 2 * I32);
                break;
            case WireCodes.BODY_RANGE_SENSOR:
                outline();
                skip(4 * F64 + I32);
                break;
            case WireCodes.BODY_PAINT_SENSOR:
                outline();
                skip(2 * F64);
                count(WireLimits.MAX_REGIONS, n -> skip((long) n * I32));
                break;
            default:
                end();
                return;
        }
        str();
        times(4, this::color);
    }

    private void outline() {
        count(WireLimits.MAX_OUTLINE_VERTICES, n -> skip((long) n * 2 * F64));
    }
}
