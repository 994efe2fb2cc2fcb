package rp1.docs;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;

/**
 * Compiles example sources (each a whole compilation unit) against the test's class path, as a user
 * would compile them against the client library, and loads the result.
 */
final class ExampleCompiler {
    private ExampleCompiler() {
    }

    /**
     * Compiles {@code sources} into {@code dir} and returns a class loader for them.
     *
     * @throws AssertionError with the compiler's messages if they do not compile
     */
    static ClassLoader compile(List<String> sources, Path dir) throws IOException {
        Path src = Files.createDirectories(dir.resolve("src"));
        Path classes = Files.createDirectories(dir.resolve("classes"));
        List<String> args = new ArrayList<>(List.of("-d", classes.toString(), "-classpath",
                System.getProperty("java.class.path"), "-encoding", "UTF-8", "-Xlint:all", "-Werror"));
        for (String source : sources) {
            Path file = src.resolve(GuideText.className(source) + ".java");
            Files.write(file, source.getBytes(StandardCharsets.UTF_8));
            args.add(file.toString());
        }
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        ByteArrayOutputStream messages = new ByteArrayOutputStream();
        int status = javac.run(null, messages, messages, args.toArray(new String[0]));
        if (status != 0) {
            throw new AssertionError("the examples do not compile:\n" + messages.toString(StandardCharsets.UTF_8));
        }
        return new URLClassLoader(new URL[] {classes.toUri().toURL()}, ExampleCompiler.class.getClassLoader());
    }
}
