/**
 * Robot logic shared by the demos that know nothing of the simulator: poses, the moves a round
 * two-wheeled robot makes, a navigation network with shortest routes, and an autopilot that drives
 * them. Nothing here imports {@code rp1.*}: as the original's user's guide recommends (docs/guide.md section 2), the same
 * code could run on a real robot behind a different interface. The demos' client classes turn
 * simulator events into calls on these classes and their decisions into requests.
 */
package rp1demo.navigation;
