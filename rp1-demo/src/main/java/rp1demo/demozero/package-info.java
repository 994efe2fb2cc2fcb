/**
 * DemoZero (User's Guide section 4.4.3): ClientZero with a small window of its own showing what the
 * robot does, piggybacked through extra event handlers without changing ClientZero's logic.
 * {@link rp1demo.demozero.DemoMain} holds a {@link rp1demo.clientzero.ClnMain} rather than extending
 * {@code RsClient}, to show that a loadable client only needs to implement {@code RsRunnable}.
 */
package rp1demo.demozero;
