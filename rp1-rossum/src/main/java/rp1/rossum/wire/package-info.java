/**
 * Internal: the wire format and what both ends of the protocol must agree on, shared by the client
 * library and the server. Not part of the client API: RP1 0.60 has no such package, programs written
 * for it never see it, and everything here may change between versions without notice.
 *
 * <p>What lives here, and why it is public: the byte helpers ({@link rp1.rossum.wire.WireIn},
 * {@link rp1.rossum.wire.WireOut}) and the limits on announced counts ({@link rp1.rossum.wire.WireLimits});
 * the protocol's numeric codes ({@link rp1.rossum.wire.WireCodes}); the request codec
 * ({@link rp1.rossum.wire.RequestCodec}) and what it decodes into, the typed
 * {@link rp1.rossum.wire.RequestListener} a server sets on its connection; the message-end scanner of
 * a non-blocking reader ({@link rp1.rossum.wire.MessageScanner}); the packing of an (event code, index)
 * pair into one key ({@link rp1.rossum.wire.EventKey}); the limits by which a motion request
 * becomes a null, straight or turning motion ({@link rp1.rossum.wire.MotionLimits}), which the server's
 * wall search must apply exactly as the body does; and the quiet closing of a connection's sockets and
 * streams ({@link rp1.rossum.wire.Closing}). The server needs all of these, and in
 * {@code rp1.rossum} they could only be package-private (0.60's API there is fixed) or public
 * additions to that API.
 *
 * <p>The codecs of bodies, plans and events stay package-private in {@code rp1.rossum}: they build
 * and read the model classes' package-private state. A server reaches them through
 * {@link rp1.rossum.RsConnection} ({@code sendEvent}, {@code encodeBodySpecification},
 * {@code decodeBodySpecification}).
 */
package rp1.rossum.wire;
