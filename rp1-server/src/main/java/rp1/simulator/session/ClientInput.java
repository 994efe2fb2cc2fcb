package rp1.simulator.session;

import rp1.simulator.scheduler.Input;

/** A client's request on its way to the boundary where its session applies it. */
public record ClientInput(ClientSession session, Request request) implements Input {
    @Override
    public int source() {
        return session.getNumber();
    }

    @Override
    public boolean isDeparture() {
        return request instanceof Request.Departure;
    }

    @Override
    public void apply(double simTime) {
        session.apply(request, simTime);
    }
}
