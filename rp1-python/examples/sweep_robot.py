#!/usr/bin/env python3
"""A robot for sweeps (``rp1 sweep ... --client 'python3 rp1-python/examples/sweep_robot.py'``).

It connects to the run's server (``RP1_HOST``, ``RP1_PORT``), asks to be placed where the run's
parameter ``param.place`` says ("home" by default), drives straight ahead at ``param.speed`` m/s
(0.2 by default) for two simulated seconds, reports its speed and the run's seed as results of its
own (columns ``result.speed`` and ``result.seed`` of results.csv), and leaves, which ends the run.
"""

import sys

import rp1client as rp


def main() -> int:
    speed = float(rp.run_parameter("speed") or "0.2")
    client = rp.Client().connect()
    body = rp.Body("Straight")
    body.add_part(rp.Circle(0.0, 0.0, 0.15))
    client.send_body_specification(body)

    def placed(event: rp.PlacementEvent) -> None:
        if event.valid:
            client.send_motion_request(rp.MotionRequest(speed, 0.0, 2.0))
        else:
            client.close()

    def halted(event: rp.MotionHaltedEvent) -> None:
        rp.report_run_result("speed", speed)
        rp.report_run_result("seed", rp.run_seed())
        client.close()

    client.add_handler(rp.PlacementEvent, placed)
    client.add_handler(rp.MotionHaltedEvent, halted)
    client.send_placement_request(rp.run_parameter("place") or "home")
    client.run()
    return 0


if __name__ == "__main__":
    sys.exit(main())
