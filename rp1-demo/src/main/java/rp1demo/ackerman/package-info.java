/**
 * The Ackerman demo: a car-like robot (steered front wheels, so it cannot turn on the spot) drives
 * a lap around the cones of FloorPlans/ackerman.txt. {@link rp1demo.ackerman.CourseDriver} steers
 * it along the course by pure pursuit, {@link rp1demo.ackerman.Main} connects it to the simulator
 * and {@link rp1demo.ackerman.Car#build()} is the body.
 */
package rp1demo.ackerman;
