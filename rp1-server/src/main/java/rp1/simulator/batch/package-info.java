/**
 * Batch runs (docs/guide.md, "Running many"): {@link rp1.simulator.batch.Batch} runs one headless
 * world per (seed, floor plan), each in a process of its own ({@link rp1.simulator.batch.SweepRun}),
 * so that a run is a function of its properties, plan and seed alone and shares nothing with the
 * others: part ids and continuity ids come from counters shared by everything in one process. Each
 * run leaves its recording, event log, picture, statistics ({@link rp1.simulator.batch.RunReport})
 * and robot trails in a folder of its own; the sweep gathers them into one table, a run's rows as
 * soon as it ends. An interrupted sweep ({@link rp1.simulator.batch.Interruption}) stops its runs
 * cleanly and keeps the finished ones; {@link rp1.simulator.batch.SweepSpec} lets {@code --resume} go
 * on with the same sweep only.
 */
package rp1.simulator.batch;
