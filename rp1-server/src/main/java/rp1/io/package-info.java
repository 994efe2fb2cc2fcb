/**
 * Files written whole or not at all ({@link rp1.io.WholeFiles}), for every output of the simulator
 * that is written at once: a sweep's tables, index and pictures, replay pages.
 */
package rp1.io;
