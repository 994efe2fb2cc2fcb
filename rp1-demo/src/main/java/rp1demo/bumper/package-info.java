/**
 * The bumper car: a demo for batch runs. Placed at a random free spot (the seed of the run decides
 * where), it drives straight until it bumps into something, backs off, turns and drives on, leaving a
 * trail. Different seeds send it different ways, which is what a sweep over seeds shows.
 */
package rp1demo.bumper;
