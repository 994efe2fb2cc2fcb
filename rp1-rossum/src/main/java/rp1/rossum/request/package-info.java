/**
 * The requests a client sends to the simulator, one class per kind, each with the handler interface
 * through which the server's {@code RsConnection} hands decoded requests to the simulator. Client
 * programs build {@link rp1.rossum.request.RsMotionRequest} and
 * {@link rp1.rossum.request.RsActuatorControlRequest} themselves; the other requests are sent through
 * the {@code send...} methods of {@code RsClient}.
 */
package rp1.rossum.request;
