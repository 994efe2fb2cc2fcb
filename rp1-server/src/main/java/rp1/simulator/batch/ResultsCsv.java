package rp1.simulator.batch;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

/** A sweep's {@code results.csv}: one row per run and robot, runs in the order they were listed. */
public final class ResultsCsv {
    /** The header row. */
    public static final String HEADER =
            "seed,plan,robot,end_time,end_reason,exit_status,x,y,heading,distance,collisions,events,wall_seconds";

    private ResultsCsv() {
    }

    /** Writes the rows of {@code outcomes} into {@code file}, replacing it. */
    public static void write(Path file, List<Batch.Outcome> outcomes) throws IOException {
        StringBuilder b = new StringBuilder(HEADER).append('\n');
        for (Batch.Outcome o : outcomes) {
            RunReport r = o.report();
            String start = o.run().seed() + "," + field(o.run().plan()) + ",";
            String run = "," + number(r.endTime()) + "," + field(r.endReason()) + "," + r.exitStatus() + ",";
            String wall = "," + String.format(Locale.ROOT, "%.3f", o.wallSeconds());
            if (r.robots().isEmpty()) {
                b.append(start).append(run).append(",,,,,").append(wall).append('\n');
            }
            for (RobotResult robot : r.robots()) {
                b.append(start).append(field(robot.name())).append(run)
                        .append(number(robot.x())).append(',').append(number(robot.y())).append(',')
                        .append(number(robot.heading())).append(',').append(number(robot.distance())).append(',')
                        .append(robot.collisions()).append(',').append(robot.events()).append(wall).append('\n');
            }
        }
        Files.write(file, b.toString().getBytes(StandardCharsets.UTF_8));
    }

    private static String number(double v) {
        return Double.isNaN(v) ? "" : Double.toString(v);
    }

    /** A text field, quoted if it holds a comma, a quote or a line break. */
    private static String field(String s) {
        if (s.indexOf(',') < 0 && s.indexOf('"') < 0 && s.indexOf('\n') < 0 && s.indexOf('\r') < 0) {
            return s;
        }
        return '"' + s.replace("\"", "\"\"") + '"';
    }
}
