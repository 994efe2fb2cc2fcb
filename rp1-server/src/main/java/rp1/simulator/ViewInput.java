package rp1.simulator;

import rp1.simulator.scheduler.Input;

/** A view's action on its way to the boundary where it is applied (source 0: before the clients' inputs). */
public record ViewInput(ViewAction action, Simulation simulation) implements Input {
    @Override
    public int source() {
        return 0;
    }

    @Override
    public void apply(double simTime) {
        action.applyTo(simulation, simTime);
    }
}
