/**
 * The demos' side of the simulator interface: conversions between RP1's events, plans and requests
 * and the simulator-free types of {@link rp1demo.navigation}. Keeping them here keeps the robot
 * logic free of {@code rp1.*} (docs/guide.md section 2).
 */
package rp1demo.adapter;
