/**
 * Immutable pictures of the world for observers (the view, picture files): which targets are
 * selected, where each robot is, which of its parts are hot and how its wheels are turned, and how
 * far each paint trail has got, at one simulation time.
 *
 * <p>A snapshot is taken on the thread running the simulation's tasks and costs a few copied numbers per robot: the body
 * parts' geometry and colours never change once a body has arrived, so a snapshot refers to the
 * parts themselves and copies only their changing state; paint-trail segments are append-only, so a
 * segment with the point count read at snapshot time is an immutable view of it.
 * {@link rp1.simulator.snapshot.SnapshotPublisher} keeps the latest snapshot for an observer on
 * another thread, taken only when the observer asks and the world changed. Nothing here draws:
 * the model never knows how (or whether) it is shown.
 */
package rp1.simulator.snapshot;
