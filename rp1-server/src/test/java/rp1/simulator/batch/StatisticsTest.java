package rp1.simulator.batch;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;

import org.junit.jupiter.api.Test;

/** The summary's statistics against values worked out by hand. */
class StatisticsTest {
    @Test
    void meanDeviationAndConfidenceIntervalOfFourValues() {
        // mean 2.5; squares 2.25 + 0.25 + 0.25 + 2.25 = 5, sd = sqrt(5/3) = 1.2909944;
        // t(0.975, 3) = 3.1824, ci95 = 3.1824 * 1.2909944 / 2 = 2.0542303
        Statistics s = Statistics.of(new double[] {1, 2, 3, 4});
        assertEquals(4, s.n());
        assertEquals(2.5, s.mean(), 1e-12);
        assertEquals(1.2909944, s.sd(), 1e-7);
        assertEquals(2.0542303, s.ci95(), 1e-6);
        assertEquals(1.0, s.min());
        assertEquals(4.0, s.max());
    }

    @Test
    void oneValueHasNoSpreadAndNoneHasNothing() {
        Statistics one = Statistics.of(new double[] {7});
        assertEquals(7.0, one.mean());
        assertEquals(Double.NaN, one.sd());
        assertEquals(Double.NaN, one.ci95());
        assertEquals(0, Statistics.of(new double[0]).n());
    }

    @Test
    void valuesAllAlikeHaveNoSpreadAtAll() {
        double[] same = new double[32];
        java.util.Arrays.fill(same, 1.7929);
        Statistics s = Statistics.of(same);
        assertEquals(1.7929, s.mean());
        assertEquals(0.0, s.sd(), "not 2.4e-16 from the rounding of the sum");
        assertEquals(0.0, s.ci95());
    }

    @Test
    void studentsTBeyondTheTableFollowsThePublishedValues() {
        assertEquals(2.0423, Statistics.t975(30), 1e-4);
        assertEquals(2.0211, Statistics.t975(40), 1e-4);
        assertEquals(2.0003, Statistics.t975(60), 1e-4);
        assertEquals(1.9799, Statistics.t975(120), 1e-4);
    }

    @Test
    void theSummaryHasARowPerConfigurationAndLeavesEmptyFieldsOut() {
        List<String> header = List.of("param.speed", "seed", "plan", "run", "robot", "end_heading", "distance",
                "first_collision_time", "result.gap", "status", "reason", "wall_seconds");
        List<List<String>> rows = List.of(
                List.of("0.3", "1", "a.txt", "runs/c1-1-a", "Bumper", "3.1", "2", "", "0.0000001", "0",
                        "max-simulation-time", "0.1"),
                List.of("0.3", "2", "a.txt", "runs/c1-2-a", "Bumper", "-3.1", "4", "3.5", "0.0000003", "0",
                        "max-simulation-time", "0.1"),
                List.of("0.5", "1", "a.txt", "runs/c2-1-a", "Bumper", "0", "6", "1.25", "1", "2", "client failed", "0.2"),
                List.of("0.5", "2", "a.txt", "runs/c2-2-a", "Bumper", "0", "8", "", "2", "0", "max-simulation-time", "0.2"));
        List<SummaryCsv.Row> summary = SummaryCsv.summarize(header, rows, List.of("param.speed"));
        List<List<String>> table = SummaryCsv.table(summary, SummaryCsv.metrics(header, List.of("param.speed")));
        // No end_heading: the plain mean of 3.1 and -3.1 rad is 0, the opposite way.
        assertEquals(List.of("param.speed", "plan", "robot", "runs", "failed", "distance_n", "distance_mean",
                "distance_sd", "distance_ci95", "distance_min", "distance_max", "first_collision_time_n",
                "first_collision_time_mean", "first_collision_time_sd", "first_collision_time_ci95",
                "first_collision_time_min", "first_collision_time_max", "result.gap_n", "result.gap_mean",
                "result.gap_sd", "result.gap_ci95", "result.gap_min", "result.gap_max", "wall_seconds_n",
                "wall_seconds_mean", "wall_seconds_sd", "wall_seconds_ci95", "wall_seconds_min", "wall_seconds_max"),
                table.get(0));
        // distance 2 and 4: mean 3, sd sqrt(2) = 1.414214, ci95 = 12.7062 * sqrt(2) / sqrt(2) = 12.7062;
        // gap 1e-7 and 3e-7: mean 2e-7, sd 1.41421356e-7, ci95 12.7062 * 1e-7 = 1.27062e-6, to 6 significant
        // digits, not 0
        assertEquals(List.of("0.3", "a.txt", "Bumper", "2", "0", "2", "3", "1.414214", "12.7062", "2", "4",
                "1", "3.5", "", "", "3.5", "3.5", "2", "0.0000002", "0.000000141421", "0.00000127062", "0.0000001",
                "0.0000003"), table.get(1).subList(0, 23));
        // The failed run is counted as failed and left out of the statistics.
        assertEquals(List.of("0.5", "a.txt", "Bumper", "2", "1", "1", "8", "", "", "8", "8", "0", "", "", "", "", "",
                "1", "2"), table.get(2).subList(0, 19));
    }

    @Test
    void aRobotsOwnResultsAreWrittenAsReportedAndStatisticsKeepSixSignificantDigits() {
        assertEquals("0.0000001", Numbers.asReported(1e-7));
        assertEquals("123456.789012345", Numbers.asReported(123456.789012345));
        assertEquals("1", Numbers.asReported(1.0));
        assertEquals("0.123457", Numbers.statistic(0.1234567));
        assertEquals("0.0123457", Numbers.statistic(0.01234567));
        assertEquals("-0.00000123457", Numbers.statistic(-0.00000123456789));
        assertEquals("7.495672", Numbers.statistic(7.4956716));
        assertEquals("0", Numbers.statistic(0.0));
    }
}
