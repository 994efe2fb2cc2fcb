package rp1.simulator.launch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * A robot of one's own, compiled outside the simulator's class path, is loaded from the folder given
 * with {@code -cp} (relative to the working directory), as {@code rp1 -cp classes -p mybot.ini} does.
 */
@Timeout(30)
class ClientClassPathTest {
    @TempDir
    Path dir;

    /** Compiles {@code mybot.Quiet}, an RsRunnable whose run() writes a file and returns, into dir/classes. */
    private void compileRobot() throws IOException {
        Path source = dir.resolve("src/mybot/Quiet.java");
        Files.createDirectories(source.getParent());
        Files.writeString(source, String.join("\n",
                "package mybot;",
                "public class Quiet implements rp1.rossum.RsRunnable {",
                "    public void setInputOutputStreams(java.io.InputStream in, java.io.OutputStream out) { }",
                "    public void setLogger(rp1.rossum.RsLogInterface log) { }",
                "    public void initialize() { }",
                "    public void run() {",
                "        try { java.nio.file.Files.writeString(java.nio.file.Path.of(\"" + dir.resolve("ran")
                        .toString().replace("\\", "\\\\") + "\"), \"yes\"); }",
                "        catch (java.io.IOException e) { throw new java.io.UncheckedIOException(e); }",
                "    }",
                "}"), StandardCharsets.UTF_8);
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        int status = javac.run(null, null, null, "-d", dir.resolve("classes").toString(),
                "-cp", System.getProperty("java.class.path"), source.toString());
        assertEquals(0, status, "the robot compiles");
    }

    private RunningServer start(String... extra) throws StartupException {
        TestServer.write(dir, "dlcEnabled=true", "dlcName=mybot.Quiet", "exitWhenClientsDone=true",
                "enableNetworkClients=false");
        List<String> args = new java.util.ArrayList<>(List.of("-p", TestServer.PROPERTIES));
        args.addAll(List.of(extra));
        return ServerLauncher.start(args.toArray(new String[0]), dir, LaunchOptions.defaults());
    }

    @Test
    void aRobotClassIsLoadedFromTheClassPathGivenRelativeToTheWorkingDirectory() throws Exception {
        compileRobot();
        RunningServer server = start("-cp", "classes");
        assertEquals(ExitStatus.OK, server.awaitExit());
        assertEquals("yes", Files.readString(dir.resolve("ran")));
    }

    @Test
    void withoutItTheClassIsNotFoundAndTheMessageSaysWhere() throws Exception {
        compileRobot();
        StartupException e = assertThrows(StartupException.class, this::start);
        assertTrue(e.getMessage().contains("mybot.Quiet not found"), e.getMessage());
    }

    @Test
    void aClassPathEntryThatDoesNotExistIsAnErrorNotASilentClassNotFound() {
        StartupException e = assertThrows(StartupException.class, () -> start("-cp", "clases"));
        assertTrue(e.getMessage().startsWith("class path entry clases not found"), e.getMessage());
    }

    @Test
    void portOnTheCommandLineReplacesThePropertiesPort() throws Exception {
        TestServer.write(dir, "port=7758");
        int free;
        try (java.net.ServerSocket s = new java.net.ServerSocket(0)) {
            free = s.getLocalPort();
        }
        RunningServer server = ServerLauncher.start(new String[] {"-p", TestServer.PROPERTIES, "--port", Integer.toString(free)},
                dir, LaunchOptions.defaults());
        try {
            assertEquals(free, server.getPort());
        } finally {
            server.stop();
        }
    }
}
