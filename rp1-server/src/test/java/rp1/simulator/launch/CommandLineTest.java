package rp1.simulator.launch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/** {@code java rp1.Server} as a user runs it: what it prints and the exit status it ends with. */
@Timeout(120)
class CommandLineTest {
    @TempDir
    Path dir;

    /** The output (both streams) and exit status of {@code java rp1.Server ARGS} run in {@code dir}. */
    private String[] server(String... args) throws IOException, InterruptedException {
        List<String> command = new ArrayList<>(Arrays.asList(
                Paths.get(System.getProperty("java.home"), "bin", "java").toString(),
                "-Djava.awt.headless=true", "-cp", System.getProperty("java.class.path"), "rp1.Server"));
        command.addAll(Arrays.asList(args));
        Process p = new ProcessBuilder(command).directory(dir.toFile()).redirectErrorStream(true).start();
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        try (InputStream in = p.getInputStream()) {
            in.transferTo(out);
        }
        if (!p.waitFor(60, TimeUnit.SECONDS)) {
            p.destroyForcibly();
            throw new AssertionError("rp1.Server " + String.join(" ", args) + " did not end");
        }
        return new String[] {out.toString(StandardCharsets.UTF_8), String.valueOf(p.exitValue())};
    }

    @Test
    void anUnknownOptionPrintsTheUsageAndExitsWithStatus1() throws Exception {
        String[] r = server("-x");
        assertEquals(String.valueOf(ExitStatus.STARTUP_FAILED), r[1], r[0]);
        assertTrue(r[0].startsWith("rp1.Server: unknown option -x\nusage: java rp1.Server [-p PROPERTIES] [-f FLOORPLAN]"), r[0]);
    }

    @Test
    void helpPrintsTheUsageAndExitsWithStatus0() throws Exception {
        String[] r = server("--help");
        assertEquals(String.valueOf(ExitStatus.OK), r[1], r[0]);
        assertTrue(r[0].startsWith("usage: java rp1.Server"), r[0]);
    }

    @Test
    void aLoadedClientClassThatDoesNotExistEndsTheServerWithStatus2() throws Exception {
        TestServer.write(dir, "dlcEnabled=true", "dlcName=no.such.Robot");
        String[] r = server("-p", TestServer.PROPERTIES);
        assertEquals(String.valueOf(ExitStatus.CLIENT_FAILED), r[1], r[0]);
        assertTrue(r[0].contains("client class no.such.Robot not found on the class path (dlcName)"), r[0]);
    }
}
