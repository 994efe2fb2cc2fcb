/**
 * The fire-fighting demo, after the Trinity College contest the User's Guide mentions: in
 * FloorPlans/contest.txt a ClientZero-shaped robot searches the rooms for a candle (a target) with
 * its target sensor and stops in front of the first one it finds. {@link rp1demo.firefighter.FireFighter}
 * is the search strategy, {@link rp1demo.firefighter.FfMain} its connection to the simulator.
 */
package rp1demo.firefighter;
