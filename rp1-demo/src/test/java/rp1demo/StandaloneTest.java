package rp1demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.ServerSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/** A demo started on its own with no simulator to talk to says so in a line, not a stack trace. */
@Timeout(60)
class StandaloneTest {
    @TempDir
    Path dir;

    @Test
    void aDemoWithNoServerPrintsOneLineAndExitsWith1() throws Exception {
        int port;
        try (ServerSocket s = new ServerSocket(0)) {
            port = s.getLocalPort();
        }
        Files.writeString(dir.resolve("rossum.ini"), "hostName=127.0.0.1\nport=" + port + "\n");
        Process p = new ProcessBuilder(Paths.get(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp", System.getProperty("java.class.path"), "rp1demo.clientzero.ClnMain")
                .directory(dir.toFile()).redirectErrorStream(true).start();
        String output = new String(p.getInputStream().readAllBytes());
        assertTrue(p.waitFor(30, TimeUnit.SECONDS));
        assertEquals(1, p.exitValue(), output);
        assertTrue(output.contains("cannot connect to the RP1 server at 127.0.0.1:" + port
                + ": is it running? start one with rp1\n"), output);
        assertFalse(output.contains("\tat "), "no stack trace: " + output);
    }

    /**
     * Each demo run on its own reads the rossum.ini of its package (README, "Demos"), which shows on the
     * console what the robot does: DemoZero had none and ran silent.
     */
    @Test
    void everyDemosPackageHasItsRossumIni() {
        for (Class<?> main : new Class<?>[] {rp1demo.clientzero.ClnMain.class, rp1demo.demozero.DemoMain.class,
            rp1demo.firefighter.FfMain.class, rp1demo.linetracker.LtMain.class, rp1demo.autopilot.ApMain.class,
            rp1demo.ackerman.Main.class, rp1demo.bumper.Bumper.class}) {
            assertTrue(main.getResource("rossum.ini") != null, main.getName() + " has no rossum.ini beside it");
        }
    }
}
