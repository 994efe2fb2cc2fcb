package rp1.simulator.launch;

/** A class named as a loaded client that is not one. */
public class NotAClient {
}
