/**
 * The events the simulator sends to a client, one class per kind (sensor readings, motion started
 * and halted, placement, position, plan, timeouts, heartbeats, encoder states, mouse clicks, target
 * selection), each with the handler interface a client implements to receive it. Handlers are
 * registered with the {@code add...EventHandler} methods of {@code RsClient} and run on the thread
 * executing its event loop.
 */
package rp1.rossum.event;
