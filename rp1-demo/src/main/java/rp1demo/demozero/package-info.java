/**
 * DemoZero (docs/guide.md section 2): ClientZero with a small window of its own showing what the
 * robot does, piggybacked through extra event handlers without changing ClientZero's logic.
 * {@link rp1demo.demozero.DemoMain} extends {@link rp1demo.clientzero.ClnMain} and keeps the
 * library's event loop, so the simulator calls its handlers directly; its window's buttons send
 * requests from Swing's thread.
 */
package rp1demo.demozero;
