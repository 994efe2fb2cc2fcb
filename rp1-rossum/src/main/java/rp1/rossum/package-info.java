/**
 * The RP1 client API: what a robot program needs to take part in a simulation. A client's session
 * with the simulator is an {@link rp1.rossum.RsClient}; the robot it describes is an
 * {@link rp1.rossum.RsBody} made of body parts (shapes, circles, sensors, painters, a wheel system
 * and its wheels); the world it receives is an {@link rp1.rossum.RsPlan} of walls, targets,
 * placements, floor paint and a navigation network; {@link rp1.rossum.RsProperties} reads its
 * configuration ({@code rossum.ini}). The server's end of a session, {@link rp1.rossum.RsConnection},
 * and the geometry and motion classes the simulator shares with clients live here too.
 *
 * <p>Names, signatures and behaviour are those of RP1 0.60, so that its client programs compile and
 * run unchanged. The messages exchanged are described in {@code docs/protocol.md}.
 */
package rp1.rossum;
