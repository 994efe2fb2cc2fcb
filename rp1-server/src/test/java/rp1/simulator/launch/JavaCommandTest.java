package rp1.simulator.launch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;

import org.junit.jupiter.api.Test;

/** The options a simulation's and a sweep's JVM start with, as the kernel's and machine's settings call for. */
class JavaCommandTest {
    @Test
    void hugePagesAreAskedForOnlyWhereTheKernelGivesThemOnRequest() {
        assertTrue(JavaCommand.hugePagesOnRequest("always [madvise] never\n"));
        assertFalse(JavaCommand.hugePagesOnRequest("[always] madvise never\n"), "the JVM gets them without asking");
        assertFalse(JavaCommand.hugePagesOnRequest("always madvise [never]\n"), "asking would only print a warning");
        assertFalse(JavaCommand.hugePagesOnRequest(""), "no such setting: not Linux");
    }

    @Test
    void aSimulationsJvmAsksForHugePagesWhereThisMachinesKernelGivesThemOnRequest() throws Exception {
        boolean onRequest = Files.isReadable(JavaCommand.HUGE_PAGES_SETTING)
                && Files.readString(JavaCommand.HUGE_PAGES_SETTING).contains("[madvise]");
        assertTrue(JavaCommand.simulatorOptions().containsAll(JavaCommand.SIMULATOR_OPTIONS));
        assertEquals(onRequest, JavaCommand.simulatorOptions().contains(JavaCommand.HUGE_PAGES),
                JavaCommand.simulatorOptions().toString());
        assertFalse(JavaCommand.sweepOptions(2).contains(JavaCommand.HUGE_PAGES), "not measured to help a sweep");
    }
}
