package rp1.simulator.scenario;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.platform.engine.discovery.ClassNameFilter.excludeClassNamePatterns;
import static org.junit.platform.engine.discovery.DiscoverySelectors.selectPackage;

import java.util.Map;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.platform.launcher.Launcher;
import org.junit.platform.launcher.LauncherDiscoveryRequest;
import org.junit.platform.launcher.TestExecutionListener;
import org.junit.platform.launcher.TestIdentifier;
import org.junit.platform.launcher.core.LauncherDiscoveryRequestBuilder;
import org.junit.platform.launcher.core.LauncherFactory;
import org.junit.platform.launcher.listeners.SummaryGeneratingListener;
import org.junit.platform.launcher.listeners.TestExecutionSummary;

/**
 * Direct delivery (loaded clients' handlers called by the simulation) is observably the same as
 * delivery through pipes: every scenario test of this package is run both ways, and each client's
 * events are byte for byte the same; and a run repeated with the same seed gives the same events.
 */
@Timeout(600)
class DeliveryEquivalenceTest {

    @Test
    void everyScenarioGivesEveryClientTheSameEventsThroughPipesAndDirectlyAndAgain() {
        Map<String, String> pipes = runScenarios("pipes");
        Map<String, String> direct = runScenarios("direct");
        Map<String, String> again = runScenarios("direct");
        assertEquals(pipes.keySet(), direct.keySet());
        int compared = 0;
        for (Map.Entry<String, String> e : pipes.entrySet()) {
            assertEquals(e.getValue(), direct.get(e.getKey()), "pipes and direct differ in " + e.getKey());
            assertEquals(direct.get(e.getKey()), again.get(e.getKey()), "two direct runs differ in " + e.getKey());
            compared += e.getValue().split("\n").length;
        }
        assertEquals(true, pipes.size() >= 40 && compared > 400,
                "scenarios compared: " + pipes.size() + ", transcript lines: " + compared);
    }

    private static Map<String, String> runScenarios(String delivery) {
        System.setProperty(Scenario.DELIVERY, delivery);
        try {
            LauncherDiscoveryRequest request = LauncherDiscoveryRequestBuilder.request()
                    .selectors(selectPackage(DeliveryEquivalenceTest.class.getPackageName()))
                    .filters(excludeClassNamePatterns(DeliveryEquivalenceTest.class.getName()))
                    .build();
            Launcher launcher = LauncherFactory.create();
            SummaryGeneratingListener summary = new SummaryGeneratingListener();
            launcher.execute(request, summary, new TestExecutionListener() {
                @Override
                public void executionStarted(TestIdentifier id) {
                    if (id.isTest()) {
                        Transcripts.begin(id.getUniqueId());
                    }
                }
            });
            TestExecutionSummary s = summary.getSummary();
            assertEquals(0, s.getTotalFailureCount(), "scenario tests failed with " + delivery + " delivery: "
                    + s.getFailures().stream().map(f -> f.getTestIdentifier().getUniqueId() + ": " + f.getException())
                    .reduce("", (a, b) -> a + "\n" + b));
            return Transcripts.take();
        } finally {
            System.clearProperty(Scenario.DELIVERY);
        }
    }
}
