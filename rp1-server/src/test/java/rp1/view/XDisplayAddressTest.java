package rp1.view;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.InetAddress;
import java.net.ServerSocket;

import org.junit.jupiter.api.Test;

/** A stale or malformed DISPLAY is recognised, so the window test falls back to a display of its own. */
class XDisplayAddressTest {

    @Test
    void aDisplayAnswersOnlyWhileSomethingListensWhereItsNumberSays() throws Exception {
        String display;
        try (ServerSocket x = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            // An ephemeral port is far above 6000, so it stands for display number port - 6000.
            display = "127.0.0.1:" + (x.getLocalPort() - 6000) + ".0";
            assertTrue(XDisplayAddress.answers(display), display);
        }
        assertFalse(XDisplayAddress.answers(display), display + " after its listener closed");
    }

    @Test
    void aLocalDisplayWithoutASocketAndAMalformedValueDoNotAnswer() {
        assertFalse(XDisplayAddress.answers(":64999"));
        assertFalse(XDisplayAddress.answers("no display here"));
    }
}
