package rp1.simulator.net;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static rp1.testing.Await.await;

import java.io.DataInputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.time.Duration;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

import rp1.rossum.RsPipe;

/** The bounded outbound queue: a client that stops reading never holds up the sender. */
@Timeout(20)
class OutboundQueueTest {
    private final List<String> failures = new CopyOnWriteArrayList<>();

    @Test
    void everyFlushIsOneMessageDeliveredInOrder() throws Exception {
        RsPipe pipe = new RsPipe();
        OutboundQueue q = OutboundQueue.start(Transport.of(pipe), 100, "writer test", failures::add);
        for (int i = 0; i < 50; i++) {
            q.write(new byte[] {0, 0, 0, (byte) i});
            q.flush();
        }
        q.flush();
        DataInputStream in = new DataInputStream(pipe.getInputStream());
        for (int i = 0; i < 50; i++) {
            assertEquals(i, in.readInt());
        }
        assertTrue(failures.isEmpty());
        q.close();
        assertEquals(-1, in.read(), "closing the queue closes the stream behind it");
    }

    @Test
    void aMessageThatFitsIsWrittenByTheSenderItself() throws Exception {
        RsPipe pipe = new RsPipe();
        OutboundQueue q = OutboundQueue.start(Transport.of(pipe), 16, "writer test", failures::add);
        q.write(new byte[] {1, 2, 3, 4, 5});
        q.flush();
        assertEquals(5, pipe.getInputStream().available(), "in the pipe when flush returns, no thread hop");
        assertEquals(0, q.getWaiting());
    }

    @Test
    void aReaderThatStopsReadingIsCutOffAtTheLimitWithoutBlockingTheSender() throws Exception {
        RsPipe nobodyReads = new RsPipe(64);
        OutboundQueue q = OutboundQueue.start(Transport.of(nobodyReads), 16, "writer test", failures::add);
        byte[] message = new byte[40];
        long start = System.nanoTime();
        IOException cutOff = assertThrows(IOException.class, () -> {
            for (int i = 0; i < 1000; i++) {
                q.write(message);
                q.flush();
            }
        });
        assertTrue(System.nanoTime() - start < TimeUnit.SECONDS.toNanos(5), "the sender was never blocked");
        assertTrue(cutOff.getMessage().contains("the limit is 16"), cutOff.getMessage());
        assertEquals(1, failures.size(), "reported once: " + failures);
        assertTrue(failures.get(0).contains("clientQueueLimit"), failures.get(0));
        assertThrows(IOException.class, () -> q.write(message), "closed for good");
    }

    @Test
    void aReaderThatStopsReadingIsCutOffOnceTheBytesWaitingPassTheBudget() throws Exception {
        RsPipe nobodyReads = new RsPipe(64);
        OutboundQueue q = OutboundQueue.start(Transport.of(nobodyReads), 10000, 4096, "writer test", failures::add);
        byte[] message = new byte[1000];
        int sent = 0;
        try {
            for (; sent < 100; sent++) {
                q.write(message);
                q.flush();
            }
        } catch (IOException cutOff) {
            assertTrue(cutOff.getMessage().contains("bytes of events waiting, the budget is 4096 (clientOutputBudget)"),
                    cutOff.getMessage());
        }
        assertTrue(sent >= 4 && sent <= 6, "cut off after about 4 KB, not 10000 messages: " + sent);
        assertEquals(1, failures.size(), "reported once: " + failures);
    }

    @Test
    void readersThatStopReadingAreCutOffOnceAllOfThemTogetherPassTheSharedBudget() throws Exception {
        // Each within its own 1 MB budget; together beyond the 10 kB all of them may have waiting.
        SharedBudget all = new SharedBudget(10_000);
        OutboundQueue first = OutboundQueue.start(Transport.of(new RsPipe(64)), 10000, 1 << 20, all, "writer 1", failures::add);
        OutboundQueue second = OutboundQueue.start(Transport.of(new RsPipe(64)), 10000, 1 << 20, all, "writer 2", failures::add);
        byte[] message = new byte[1000];
        for (int i = 0; i < 6; i++) {
            first.write(message);
            first.flush();
        }
        IOException cutOff = assertThrows(IOException.class, () -> {
            for (int i = 0; i < 6; i++) {
                second.write(message);
                second.flush();
            }
        });
        assertTrue(cutOff.getMessage().contains("the events waiting for all the clients would hold more than 10000 bytes"),
                cutOff.getMessage());
        assertEquals(1, failures.size(), "the second alone: " + failures);
        first.close();
        assertEquals(0, all.held(), "closed queues let go of what they held");
    }

    @Test
    void oneMessageLargerThanTheBudgetMayStillWait() throws Exception {
        RsPipe slow = new RsPipe(64);
        OutboundQueue q = OutboundQueue.start(Transport.of(slow), 10000, 4096, "writer test", failures::add);
        q.write(new byte[10000]);
        q.flush();
        assertEquals(1, q.getWaiting());
        assertEquals(List.of(), failures);
        q.close();
    }

    @Test
    void aFailingStreamIsReportedAndLaterWritesFail() throws Exception {
        OutputStream broken = new OutputStream() {
            @Override
            public void write(int b) throws IOException {
                throw new IOException("connection reset");
            }
        };
        OutboundQueue q = OutboundQueue.start(Transport.of(broken), 16, "writer test", failures::add);
        q.write(1);
        q.flush();
        await(() -> !failures.isEmpty(), Duration.ofSeconds(10), "the writer thread reported the failure");
        assertEquals(List.of("cannot write to the client: connection reset"), failures);
        assertThrows(IOException.class, () -> q.write(2));
    }

    /**
     * Every call the queue makes on the transport is recorded, so what went out and when is known
     * without waiting to see whether something else happens: the first call is the flush's attempt.
     */
    @Test
    void bytesWrittenBeforeAFlushStayTogether() throws Exception {
        List<String> calls = new CopyOnWriteArrayList<>();
        Transport recording = new Transport() {
            @Override
            public int tryWrite(byte[] b, int off, int len) {
                calls.add("try " + Arrays.toString(Arrays.copyOfRange(b, off, off + len)));
                return 0;
            }

            @Override
            public void write(byte[] b, int off, int len) {
                calls.add("write " + Arrays.toString(Arrays.copyOfRange(b, off, off + len)));
            }

            @Override
            public void close() {
            }
        };
        OutboundQueue q = OutboundQueue.start(recording, 16, "writer test", failures::add);
        q.write(new byte[] {1, 2});
        q.write(3);
        assertEquals(List.of(), calls, "nothing goes out before the flush");
        q.flush();
        await(() -> q.getWaiting() == 0, Duration.ofSeconds(10), "the writer thread wrote the queued message");
        assertEquals(List.of("try [1, 2, 3]", "write [1, 2, 3]"), calls, "the flush offered the whole message at once");
    }
}
