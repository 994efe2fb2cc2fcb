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
 * run unchanged. The messages exchanged are described in {@code docs/protocol.md}. The few public
 * types and members beyond 0.60 are there on purpose; the library's tests keep a list of them, each
 * with its reason, and fail on any other.
 *
 * <p>Internal classes, package-private and free to change: the codecs of a body specification
 * ({@code BodyCodec}), of a plan event ({@code PlanCodec}) and of the other events
 * ({@code EventCodec}), which build and read the model's package-private state; a connection's
 * feed-mode framing ({@code FeedDecoder}) and 0.60's per-type request handlers
 * ({@code ConnectionHandlers}); the client's table of event handlers ({@code HandlerRegistry}); and
 * model helpers ({@code MotionRequests}, {@code BodyOutline}, {@code SweptContact},
 * {@code PlanLabels}, {@code PlanPolygons}). What the server shares with the library (byte helpers,
 * protocol codes, the request codec and its listener) is in the internal package
 * {@code rp1.rossum.wire}, which is not client API.
 *
 * <p>Where collisions live: the simulator's robots are {@link rp1.rossum.RsBody} objects, so
 * collisions with walls are computed here. When a motion starts, {@code RsBody} flags the contact
 * sensors and cuts the motion before its first contact with a wall, found over the whole motion at
 * once by the swept-contact search ({@code SweptContact}, reached through
 * {@link rp1.rossum.RsMotion}). Robots touching other robots are the simulator's business (RP1 0.60
 * let them pass through each other): see {@code rp1.simulator.world.RobotContacts} in the server.
 */
package rp1.rossum;
