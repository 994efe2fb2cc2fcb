package rp1.view;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketAddress;
import java.net.StandardProtocolFamily;
import java.net.UnixDomainSocketAddress;
import java.nio.channels.SocketChannel;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Where the X server named by a {@code DISPLAY} value listens, and whether it accepts a connection
 * there: {@code :N} (or {@code unix:N}) is the local socket {@code /tmp/.X11-unix/XN},
 * {@code HOST:N} is TCP port 6000 + N on HOST. Only the connection is tried, no X request is made.
 */
final class XDisplayAddress {
    private static final Pattern DISPLAY = Pattern.compile("(.*):(\\d+)(\\.\\d+)?");
    private static final int X_TCP_BASE = 6000;
    private static final int CONNECT_MILLIS = 2000;

    private XDisplayAddress() {
    }

    /** Whether an X server accepts connections at {@code display}; false if the value is malformed. */
    static boolean answers(String display) {
        Matcher m = DISPLAY.matcher(display);
        if (!m.matches()) {
            return false;
        }
        String host = m.group(1);
        int number = Integer.parseInt(m.group(2));
        try {
            if (host.isEmpty() || host.equals("unix")) {
                return acceptsLocal(Paths.get("/tmp/.X11-unix/X" + number));
            }
            return acceptsTcp(new InetSocketAddress(host, X_TCP_BASE + number));
        } catch (IOException e) {
            return false;
        }
    }

    private static boolean acceptsLocal(Path socket) throws IOException {
        if (!Files.exists(socket)) {
            return false;
        }
        SocketAddress address = UnixDomainSocketAddress.of(socket);
        try (SocketChannel channel = SocketChannel.open(StandardProtocolFamily.UNIX)) {
            return channel.connect(address);
        }
    }

    private static boolean acceptsTcp(InetSocketAddress address) throws IOException {
        try (Socket socket = new Socket()) {
            socket.connect(address, CONNECT_MILLIS);
            return true;
        }
    }
}
