package rp1.simulator.launch;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * One client cannot make the server hold more than its budgets (docs/properties.md): each flood
 * below ends with the client disconnected, a log line naming the budget, and the server serving the
 * next client. The floods are a few hundred messages over loopback.
 */
@Timeout(60)
class ClientBudgetsTest {
    private static final String OVER = ": RsConnection terminating due to exception on input: over budget: ";

    @TempDir
    Path dir;

    private static String who(RawClient c) {
        return "(/127.0.0.1:" + c.socket.getLocalPort() + ")";
    }

    private RunningServer server(String... budgets) throws StartupException {
        String[] lines = new String[budgets.length + 2];
        lines[0] = "simulationSpeed=10";
        lines[1] = "waitForClients=0";
        System.arraycopy(budgets, 0, lines, 2, budgets.length);
        return TestServer.start(dir, lines);
    }

    /** Sends what {@code flood} writes; the server may hang up before the end, as it should. */
    private interface Flood {
        void send(RawClient c, int i) throws IOException;
    }

    private static void flood(RawClient c, int count, Flood flood) {
        try {
            for (int i = 0; i < count; i++) {
                flood.send(c, i);
            }
            c.out.flush();
        } catch (IOException hungUp) {
            // The server closed the connection once the client was over its budget.
        }
    }

    private static void assertStillServing(RunningServer server) throws IOException {
        try (RawClient late = RawClient.connected(server.getPort())) {
            late.sendTimeout(0.0, 7);
            assertEquals(7, late.awaitEvent(RawClient.EVT_TIMEOUT).value, "the server still serves");
        }
    }

    @Test
    void aClientAskingForMoreTimeoutsThanItsBudgetIsDisconnected() throws Exception {
        RunningServer server = server("clientTimeoutBudget=4096");
        try (RawClient c = RawClient.connected(server.getPort())) {
            flood(c, 200, (r, i) -> {
                r.request(0);
                r.out.writeDouble(1000.0);
                r.out.writeInt(i);
            });
            TestServer.awaitLog(dir, who(c) + OVER + "17 pending timeouts count 4352 bytes, the budget is 4096 "
                    + "(clientTimeoutBudget)");
            TestServer.awaitLog(dir, who(c) + " disconnected");
            assertStillServing(server);
        } finally {
            server.stop();
        }
    }

    @Test
    void aClientSubscribingBeyondItsBudgetIsDisconnected() throws Exception {
        RunningServer server = server("clientSubscriptionBudget=4096");
        try (RawClient c = RawClient.connected(server.getPort())) {
            flood(c, 200, (r, i) -> {
                r.request(1);
                r.out.writeInt(0);
                r.out.writeInt(i);
                r.out.writeBoolean(true);
            });
            TestServer.awaitLog(dir, "subscriptions count ");
            TestServer.awaitLog(dir, "bytes, the budget is 4096 (clientSubscriptionBudget)");
            TestServer.awaitLog(dir, who(c) + " disconnected");
            assertStillServing(server);
        } finally {
            server.stop();
        }
    }

    @Test
    void aClientThatAsksForPlansAndReadsNoneIsDisconnectedOnceTheyFillItsOutputBudget() throws Exception {
        RunningServer server = server("clientOutputBudget=65536");
        try (RawClient c = RawClient.openWithSmallBuffer(server.getPort())) {
            c.handshake(0, 0);
            flood(c, 5000, (r, i) -> r.request(9));
            TestServer.awaitLog(dir, who(c) + ": closing the connection: not reading: ");
            TestServer.awaitLog(dir, "bytes of events waiting, the budget is 65536 (clientOutputBudget)");
            assertStillServing(server);
        } finally {
            server.stop();
        }
    }

    @Test
    void aClientWhoseMessageOutgrowsItsBudgetIsDisconnected() throws Exception {
        RunningServer server = server("clientMessageBudget=65536");
        try (RawClient c = RawClient.connected(server.getPort())) {
            c.header(RawClient.BODY);
            c.out.writeUTF("long");
            c.out.writeInt(1);
            c.out.writeInt(1);
            c.out.writeInt(3);
            c.out.writeInt(60000);
            flood(c, 10000, (r, i) -> r.out.writeDouble(i));
            TestServer.awaitLog(dir, who(c) + OVER + "an incomplete message of ");
            TestServer.awaitLog(dir, "bytes, the budget is 65536 (clientMessageBudget)");
            TestServer.awaitLog(dir, who(c) + " disconnected");
            assertStillServing(server);
        } finally {
            server.stop();
        }
    }
}
