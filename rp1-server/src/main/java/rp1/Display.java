package rp1;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.UnixDomainSocketAddress;
import java.nio.channels.SocketChannel;
import java.nio.file.Path;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Whether an X display answers, asked without starting AWT: once AWT has failed to open a display it
 * cannot be switched to headless any more, so the {@code rp1} command asks first and then starts the
 * JVM's AWT either way it has to be.
 */
final class Display {
    /** {@code [host]:display[.screen]} as X11 writes DISPLAY. */
    private static final Pattern X11 = Pattern.compile("([^:/]*):(\\d+)(\\.\\d+)?");
    private static final int CONNECT_MILLIS = 2000;

    private Display() {
    }

    /**
     * Whether {@code display} (the value of DISPLAY, or null) names an X server that accepts a
     * connection. A value this does not understand (a launchd socket path, say) counts as answering:
     * the window then tries it and says why if it fails.
     */
    static boolean answers(String display) {
        if (display == null || display.isBlank()) {
            return false;
        }
        Matcher m = X11.matcher(display.trim());
        if (!m.matches()) {
            return true;
        }
        int number = Integer.parseInt(m.group(2));
        String host = m.group(1);
        if (host.isEmpty() || host.equals("unix")) {
            return local(number);
        }
        return tcp(host, 6000 + number);
    }

    private static boolean local(int number) {
        Path socket = Path.of("/tmp/.X11-unix/X" + number);
        try {
            // Connecting is the whole probe: the channel is closed at once.
            SocketChannel.open(UnixDomainSocketAddress.of(socket)).close();
            return true;
        } catch (IOException | UnsupportedOperationException e) {
            // Some X servers listen only on TCP even for ":N".
            return tcp("localhost", 6000 + number);
        }
    }

    private static boolean tcp(String host, int port) {
        try (Socket s = new Socket()) {
            s.connect(new InetSocketAddress(host, port), CONNECT_MILLIS);
            return true;
        } catch (IOException | IllegalArgumentException e) {
            return false;
        }
    }
}
