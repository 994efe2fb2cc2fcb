/**
 * What a run's robots did, gathered while it runs by an observer that changes nothing
 * ({@link rp1.simulator.outcome.RunStatistics}): each robot's result
 * ({@link rp1.simulator.outcome.RobotResult}: where it started and ended, how far it went, its
 * collisions, events and reported results) and the path it took ({@link rp1.simulator.outcome.Trail}).
 * A sweep writes them as a run's row and trails file; the view draws the trails in its pictures.
 */
package rp1.simulator.outcome;
