/**
 * Batch runs (docs/guide.md, "Running many" and "Experiments"): {@link rp1.simulator.batch.Batch}
 * runs one headless world per configuration of the varied keys ({@link rp1.simulator.batch.Varied}),
 * seed and floor plan, so that a run is a function of its properties, plan and seed alone and shares
 * nothing with the others: in the sweep's own process, each with a server, a world and a class loader
 * for the robot's classes of its own ({@link rp1.simulator.batch.LoaderRuns}), or each in a process of
 * its own ({@link rp1.simulator.batch.ProcessRuns}). Each run leaves its recording, event log,
 * statistics ({@link rp1.simulator.batch.RunReport}) and robot trails in a folder of its own; the
 * sweep gathers them into one table, a run's rows as soon as it ends, and sums them up per
 * configuration ({@link rp1.simulator.batch.SummaryCsv}). An interrupted sweep
 * ({@link rp1.simulator.batch.Interruption}) stops its runs cleanly and keeps the finished ones;
 * {@link rp1.simulator.batch.SweepSpec} lets {@code --resume} go on with the same sweep only.
 */
package rp1.simulator.batch;
