package rp1.simulator.batch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.util.List;

import org.junit.jupiter.api.Test;

import rp1.rossum.RsClient;

/** Each run's loader gives the robot classes of its own, from what the sweep worked out once. */
class RunClassLoaderTest {
    private static final String ROBOT = ExperimentDlc.class.getName();

    @Test
    void everyRunLoadsTheRobotAfreshAndSharesTheLibrary() throws Exception {
        ClassLoader sweep = RunClassLoaderTest.class.getClassLoader();
        RunClassLoader.Source source = RunClassLoader.source(List.of(ROBOT), sweep);
        try (RunClassLoader first = source.newLoader(); RunClassLoader second = source.newLoader()) {
            Class<?> a = first.loadClass(ROBOT);
            Class<?> b = second.loadClass(ROBOT);
            assertNotSame(a, b, "each run has a robot class of its own");
            assertNotSame(ExperimentDlc.class, a, "and not the sweep's");
            assertSame(first, a.getClassLoader());
            // The library, asked through the robot's class and through the loader, is the sweep's in both runs.
            assertSame(RsClient.class, a.getSuperclass());
            assertSame(RsClient.class, b.getSuperclass());
            assertSame(RsClient.class, second.loadClass(RsClient.class.getName()));
            assertSame(String.class, first.loadClass("java.lang.String"));
        }
    }

    @Test
    void theSharingDecisionIsTheSameForEveryRun() throws Exception {
        RunClassLoader.Source source = RunClassLoader.source(List.of(ROBOT), RunClassLoaderTest.class.getClassLoader());
        assertEquals(true, source.isShared(RsClient.class.getName()));
        assertEquals(false, source.isShared(ROBOT));
        assertEquals(false, source.isShared("no.such.Robot"), "what no one has is looked for in the run's own path");
        assertEquals(true, source.isShared(RsClient.class.getName()), "asked again");
        assertEquals(false, source.isShared(ROBOT), "asked again");
    }
}
