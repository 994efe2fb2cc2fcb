package rp1.simulator.launch;

import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/** The command line that runs a class in a new JVM like this one: this Java, this class path, headless. */
public final class JavaCommand {
    private JavaCommand() {
    }

    /**
     * {@code java [jvmOptions] -Djava.awt.headless=true -cp CLASSPATH mainClass [args]}, with this
     * process's Java and class path.
     */
    public static List<String> of(List<String> jvmOptions, String mainClass, String... args) {
        List<String> command = new ArrayList<>();
        command.add(Paths.get(System.getProperty("java.home"), "bin", "java").toString());
        command.addAll(jvmOptions);
        command.addAll(List.of("-Djava.awt.headless=true", "-cp", System.getProperty("java.class.path"), mainClass));
        command.addAll(Arrays.asList(args));
        return command;
    }
}
