/**
 * Recording a run and replaying it (docs/recording.md). A {@link rp1.simulator.record.Recorder}
 * writes down what a run was made of: its properties, floor-plan text and seed, and every input
 * (client requests and bodies, departures, the view's mouse clicks) with the place in the task
 * sequence and the simulated time at which it took effect. The run's inputs are the only thing from
 * outside that changes the model, and the task sequence is a function of them, so a
 * {@link rp1.simulator.record.Replayer} that runs the same tasks and applies each input before the
 * same task rebuilds the run exactly, without any client and without the wall clock, however the run
 * was paced. The {@link rp1.simulator.record.EventStream} writes every event sent in one stable text
 * line, the form in which two runs are compared.
 */
package rp1.simulator.record;
