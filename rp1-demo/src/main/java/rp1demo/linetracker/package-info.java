/**
 * The line-tracking demo: a small two-wheeled robot follows the painted loop of
 * FloorPlans/linetrack.txt with two paint sensors, one each side of the line's middle.
 * {@link rp1demo.linetracker.LineFollower} turns what the sensors see into wheel speeds,
 * {@link rp1demo.linetracker.LtMain} connects it to the simulator and
 * {@link rp1demo.linetracker.LineTracker#build()} is the body.
 */
package rp1demo.linetracker;
