package rp1.rossum.badini;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

import rp1.rossum.RsClient;
import rp1.rossum.RsLogAdapter;

/**
 * A client whose packaged {@code rossum.ini} (beside this class) is invalid: {@code initialize()}
 * keeps the defaults and says so in the client's log, not on standard error.
 */
class BadIniClientTest {
    @Test
    void anInvalidPropertiesFileIsReportedInTheClientsLog() throws Exception {
        List<String> log = new ArrayList<>();
        RsClient client = new RsClient() {
        };
        client.setLogger(new RsLogAdapter() {
            @Override
            public void logIt(String level, String message) {
                log.add(level + " " + message);
            }
        });
        client.setInputOutputStreams(new ByteArrayInputStream(new byte[0]), new ByteArrayOutputStream());
        client.initialize();
        assertEquals(List.of("X RsClient: Bad number format for integer port specification: \"seven\" (resource "
                + "rossum.ini of " + client.getClass().getName() + "); using defaults"), log);
        assertEquals(7758, client.getProperties().port, "the defaults stay");
    }
}
