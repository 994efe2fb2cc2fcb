package rp1.rossum;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.util.Random;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** The in-process pipe: ordered delivery through a small buffer, and closing either end releases the other. */
@Timeout(30)
class RsPipeTest {

    @Test
    void bytesArriveInOrderThroughABufferMuchSmallerThanTheData() throws Exception {
        RsPipe pipe = new RsPipe(7);
        byte[] data = new byte[100_000];
        new Random(1).nextBytes(data);
        CompletableFuture<Void> writer = CompletableFuture.runAsync(() -> {
            try (OutputStream out = pipe.getOutputStream()) {
                for (int i = 0; i < data.length; i += 13) {
                    out.write(data, i, Math.min(13, data.length - i));
                }
            } catch (IOException e) {
                throw new RuntimeException(e);
            }
        });
        ByteArrayOutputStream got = new ByteArrayOutputStream();
        byte[] buf = new byte[5];
        InputStream in = pipe.getInputStream();
        for (int n; (n = in.read(buf)) >= 0; ) {
            got.write(buf, 0, n);
        }
        writer.get(10, TimeUnit.SECONDS);
        assertArrayEquals(data, got.toByteArray());
    }

    @Test
    void aWriterThreadThatEndsDoesNotBreakTheReader() throws Exception {
        RsPipe pipe = new RsPipe();
        Thread t = new Thread(() -> {
            try {
                pipe.getOutputStream().write(new byte[] {1, 2, 3});
            } catch (IOException e) {
                throw new RuntimeException(e);
            }
        });
        t.start();
        t.join();
        byte[] three = new byte[3];
        assertEquals(3, pipe.getInputStream().read(three));
        assertArrayEquals(new byte[] {1, 2, 3}, three);
    }

    @Test
    void closingTheReaderReleasesABlockedWriter() throws Exception {
        RsPipe pipe = new RsPipe(4);
        CompletableFuture<Void> writer = CompletableFuture.runAsync(() -> {
            try {
                pipe.getOutputStream().write(new byte[64]);
            } catch (IOException e) {
                throw new RuntimeException(e);
            }
        });
        Thread.sleep(50);
        pipe.getInputStream().close();
        Throwable cause = assertThrows(Exception.class, () -> writer.get(10, TimeUnit.SECONDS)).getCause().getCause();
        assertEquals("pipe closed by its reader", cause.getMessage());
    }

    @Test
    void closingTheWriterEndsTheStreamAfterTheBufferedBytes() throws Exception {
        RsPipe pipe = new RsPipe();
        pipe.getOutputStream().write(new byte[] {9, 8});
        pipe.getOutputStream().close();
        InputStream in = pipe.getInputStream();
        assertEquals(9, in.read());
        assertEquals(8, in.read());
        assertEquals(-1, in.read());
    }
}
