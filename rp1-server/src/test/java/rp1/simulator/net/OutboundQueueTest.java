package rp1.simulator.net;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.IOException;
import java.io.OutputStream;
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
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (failures.isEmpty() && System.nanoTime() < deadline) {
            Thread.sleep(1);
        }
        assertEquals(List.of("cannot write to the client: connection reset"), failures);
        assertThrows(IOException.class, () -> q.write(2));
    }

    @Test
    void bytesWrittenBeforeAFlushStayTogether() throws Exception {
        ByteArrayOutputStream sink = new ByteArrayOutputStream();
        OutboundQueue q = OutboundQueue.start(Transport.of(sink), 16, "writer test", failures::add);
        q.write(new byte[] {1, 2});
        q.write(3);
        Thread.sleep(20);
        assertEquals(0, sink.size(), "nothing goes out before the flush");
        q.flush();
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (q.getWaiting() > 0 && System.nanoTime() < deadline) {
            Thread.sleep(1);
        }
        assertArrayEquals(new byte[] {1, 2, 3}, sink.toByteArray());
    }
}
