package rp1.simulator.config;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A properties file or floor plan named after a folder is said to be one, not missing. */
class ResourceLocatorTest {
    @TempDir
    Path dir;

    @Test
    void aFolderWhereAFileShouldBeIsSaidToBeAFolder() throws Exception {
        Files.createDirectories(dir.resolve("adir"));
        ResourceLocator locator = new ResourceLocator(dir, ResourceLocatorTest.class.getClassLoader());
        ConfigException properties = assertThrows(ConfigException.class, () -> locator.properties("adir"));
        assertEquals("properties adir: " + dir.resolve("adir").toAbsolutePath() + " is a folder, not a file",
                properties.getMessage());
        ConfigException plan = assertThrows(ConfigException.class, () -> locator.plan("adir"));
        assertEquals("floor plan adir: " + dir.resolve("adir").toAbsolutePath() + " is a folder, not a file",
                plan.getMessage());
    }
}
