package rp1.rossum.request;

/** Server side: handles painter-change requests read by an {@code RsConnection}. */
public interface RsPainterChangeRequestHandler extends RsRequestHandler {
    void process(RsPainterChangeRequest request);
}
