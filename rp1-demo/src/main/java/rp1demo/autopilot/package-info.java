/**
 * The autopilot demo: in the contest arena (FloorPlans/contest.txt) a ClientZero-shaped robot
 * tours the house along the floor plan's navigation network, visiting every room by the shortest
 * route and coming home. {@link rp1demo.autopilot.Tour} decides where to go next;
 * {@link rp1demo.autopilot.ApMain} connects it to the simulator.
 */
package rp1demo.autopilot;
