package rp1.rossum;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import javax.tools.Diagnostic;
import javax.tools.DiagnosticCollector;
import javax.tools.JavaCompiler;
import javax.tools.JavaFileObject;
import javax.tools.StandardJavaFileManager;
import javax.tools.ToolProvider;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Every public and protected member of the client library has a javadoc comment: the compiler's
 * doclint, asked for missing comments down to protected access ({@code -Xdoclint:missing/protected}),
 * reports none. Missing {@code @param} and {@code @return} tags are reported too; those are allowed.
 */
class ApiMemberJavadocTest {
    @TempDir
    Path out;

    @Test
    void everyPublicAndProtectedMemberHasAComment() throws IOException {
        String root = System.getProperty("rp1.root");
        assertNotNull(root, "system property rp1.root (the project directory) is not set");
        Path sources = Paths.get(root, "rp1-rossum", "src", "main", "java");
        List<Path> files;
        try (Stream<Path> all = Files.walk(sources)) {
            files = all.filter(p -> p.toString().endsWith(".java")).collect(Collectors.toList());
        }
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        DiagnosticCollector<JavaFileObject> diagnostics = new DiagnosticCollector<>();
        try (StandardJavaFileManager fm = javac.getStandardFileManager(diagnostics, Locale.ROOT, StandardCharsets.UTF_8)) {
            List<String> options = List.of("-Xdoclint:missing/protected", "-Xmaxwarns", "100000", "-proc:none",
                    "-encoding", "UTF-8", "-d", out.toString());
            javac.getTask(null, fm, diagnostics, options, null, fm.getJavaFileObjectsFromPaths(files)).call();
        }
        List<String> missing = new ArrayList<>();
        for (Diagnostic<? extends JavaFileObject> d : diagnostics.getDiagnostics()) {
            if (d.getSource() == null) {
                missing.add(d.getKind() + ": " + d.getMessage(Locale.ROOT));
            } else if (d.getKind() == Diagnostic.Kind.ERROR || d.getMessage(Locale.ROOT).equals("no comment")) {
                Path file = Paths.get(d.getSource().toUri());
                missing.add(sources.relativize(file) + ":" + d.getLineNumber() + ": " + d.getMessage(Locale.ROOT) + ": "
                        + Files.readAllLines(file, StandardCharsets.UTF_8).get((int) d.getLineNumber() - 1).trim());
            }
        }
        assertEquals("", String.join("\n", missing), "public or protected members without a javadoc comment");
    }
}
