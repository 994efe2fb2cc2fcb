package rp1.rossum;

import java.io.ByteArrayOutputStream;

/** Hex dumps as protocol.md writes them: groups of hex digits, white space ignored. */
final class Hex {
    private Hex() {
    }

    /** The bytes of a hex dump such as {@code "00000001 0002 4142"}. */
    static byte[] bytes(String hex) {
        String digits = hex.replaceAll("\\s+", "");
        if (digits.length() % 2 != 0) {
            throw new IllegalArgumentException("odd number of hex digits: " + hex);
        }
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        for (int i = 0; i < digits.length(); i += 2) {
            out.write(Integer.parseInt(digits.substring(i, i + 2), 16));
        }
        return out.toByteArray();
    }

    /** A compact dump for assertion messages. */
    static String of(byte[] bytes) {
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < bytes.length; i++) {
            if (i > 0 && i % 4 == 0) {
                b.append(' ');
            }
            b.append(String.format("%02x", bytes[i] & 0xFF));
        }
        return b.toString();
    }
}
