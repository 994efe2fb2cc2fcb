package rp1.simulator.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

import rp1.rossum.RsBody;
import rp1.simulator.noise.RobotNoise;

/** Robots come due earliest first, those due together in joining order, however they were filed. */
class DueRobotsTest {
    private final List<Robot> robots = new ArrayList<>();
    private final DueRobots due = new DueRobots();
    private final OutlineSources sources = new OutlineSources();

    private Robot robot(int n) {
        while (robots.size() <= n) {
            robots.add(new Robot(robots.size(), new RsBody("r" + robots.size()), EventSinks.NOWHERE, RobotNoise.NONE,
                    sources));
        }
        return robots.get(n);
    }

    private List<Integer> takeDueBy(double time) {
        List<Robot> taken = new ArrayList<>();
        due.takeDueBy(time, taken);
        List<Integer> numbers = new ArrayList<>();
        taken.forEach(r -> numbers.add(r.getNumber()));
        return numbers;
    }

    @Test
    void robotsComeOutByTimeThenNumber() {
        due.put(robot(5), 0.1);
        due.put(robot(2), 0.15);
        due.put(robot(9), 0.1);
        due.put(robot(0), 0.1);
        due.put(robot(7), 0.05);
        assertEquals(0.05, due.first());
        assertEquals(List.of(7, 0, 5, 9), takeDueBy(0.1));
        assertFalse(due.isDue(robot(5)));
        assertEquals(List.of(2), takeDueBy(1.0));
        assertTrue(due.isEmpty());
    }

    @Test
    void aRobotFiledAgainIsDueOnlyAtItsNewTime() {
        due.put(robot(3), 0.2);
        due.put(robot(1), 0.2);
        due.put(robot(3), 0.12);
        assertEquals(0.12, due.dueTime(robot(3)));
        assertEquals(List.of(3), takeDueBy(0.15));
        due.put(robot(1), 0.3);
        assertEquals(List.of(), takeDueBy(0.25));
        assertEquals(List.of(1), takeDueBy(0.3));
    }

    @Test
    void aRemovedRobotIsNotDueAndAnEmptyTimeGoes() {
        due.put(robot(4), 0.5);
        due.put(robot(6), 0.7);
        due.remove(robot(4));
        due.remove(robot(4));
        assertFalse(due.isDue(robot(4)));
        assertEquals(0.7, due.first());
        assertEquals(List.of(6), takeDueBy(1.0));
    }
}
