package rp1.simulator.batch;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import rp1.rossum.RsClient;

/** A robot that deletes the file its run's parameter {@code delete} names, as a user cleaning up too soon would, then leaves. */
public class VandalDlc extends RsClient {
    @Override
    public void initialize() throws IOException {
        super.initialize();
        Files.deleteIfExists(Path.of(getRunParameter("delete")));
        sendBodySpecification(Disc.named("vandal", 0.1));
        addPlacementEventHandler(e -> shutdown());
        sendPlacementRequest("home");
    }
}
