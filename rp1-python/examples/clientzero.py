#!/usr/bin/env python3
"""ClientZero in Python: the RP1 User's Guide's first robot.

A round robot 0.3 m across on two wheels, with a target sensor ("head") looking ahead over 45
degrees and 1 m. It asks for the floor plan and the placement "home"; then a left click on the
simulator's floor plan sends it to the clicked point along an arc, and any other click turns it on
the spot to face the point. After running into a wall it waits half a second and backs off 5 cm so
it is free to turn again. It runs until the simulator closes the connection (or Ctrl-C).

    python clientzero.py --host 127.0.0.1 --port 7758
"""

import math
import sys
from typing import List, Optional, Tuple

import rp1client as rp
from connection import PLACEMENT_REFUSED, argument_parser, connect, run_main

SPEED = 0.25
BACK_OFF_DELAY = 0.5
BACK_OFF_SPEED = 0.1
BACK_OFF_DISTANCE = 0.05


def build_body() -> rp.Body:
    """ClientZero's body: the chassis, the head, then the wheels so that they are drawn on top."""
    body = rp.Body("ClientZero")
    steering = rp.DifferentialSteering(0.18, 0.075)
    steering.add_default_wheels(0.075, 0.03)
    steering.set_color(rp.Color.DARK_GRAY)
    chassis = rp.Circle(0.0, 0.0, 0.15)
    chassis.name = "main chassis"
    chassis.fill_color = rp.Color.LIGHT_GRAY
    chassis.line_color = rp.Color.DARK_GRAY
    head = rp.TargetSensor([(0.09, -0.025), (0.16, -0.025), (0.16, 0.025), (0.09, 0.025)],
                           0.16, 0.0, 0.0, math.radians(45.0), 1.0, 3, 3)
    head.name = "head"
    head.set_color(rp.Color.BLUE)
    for part in (chassis, head, steering):
        body.add_part(part)
    return body


def to_robot_frame(x: float, y: float, heading: float, px: float, py: float) -> Tuple[float, float]:
    """Point (px, py) seen from a robot at (x, y) facing ``heading``: metres ahead, metres to the left."""
    dx, dy = px - x, py - y
    c, s = math.cos(heading), math.sin(heading)
    return c * dx + s * dy, -s * dx + c * dy


class ClientZero:
    """Turns clicks into motions: a click asks for the robot's position, and the position event
    starts the motion towards the clicked point (using the true position keeps the demo short)."""

    def __init__(self, client: rp.Client, body: rp.Body) -> None:
        self.client = client
        self.body = body
        self.goal: Optional[Tuple[bool, float, float]] = None
        self.back_off_timeout = -1

    def register(self) -> None:
        c = self.client
        c.add_handler(rp.MouseClickEvent, self.on_click)
        c.add_handler(rp.PositionEvent, self.on_position)
        c.add_handler(rp.PlacementEvent, self.on_placement)
        c.add_handler(rp.MotionHaltedEvent, self.on_halted)
        c.add_handler(rp.TargetSensorEvent, self.on_head, self.body.part_by_name("head"))
        c.add_handler(rp.TargetSelectionEvent, lambda e: say(f"target {e.target_name} selected: {e.status}"))
        c.add_handler(rp.TimeoutEvent, self.on_timeout)
        c.add_handler(rp.PlanEvent, lambda e: say(f"floor plan {e.plan.caption!r}" if e.plan else "no floor plan"))

    def on_click(self, e: rp.MouseClickEvent) -> None:
        go = e.button == 0
        say(f"mouse click at ({e.x:.3f}, {e.y:.3f}): {'going there' if go else 'turning to face it'}")
        self.goal = (go, e.x, e.y)
        self.client.send_position_request()

    def on_position(self, e: rp.PositionEvent) -> None:
        if self.goal is None:
            say(f"position ({e.x:.3f}, {e.y:.3f}) heading {math.degrees(e.orientation):.1f} deg")
            return
        go, gx, gy = self.goal
        self.goal = None
        x, y = to_robot_frame(e.x, e.y, e.orientation, gx, gy)
        wheels = self.body.wheel_system
        request = wheels.get_motion_request(x, y, SPEED) if go else wheels.get_motion_request_for_pivot(x, y, SPEED)
        if request is None:
            say("already there")
            return
        say(f"{request.linear_velocity:.3f} m/s, {request.rotational_velocity:.3f} rad/s for {request.duration:.2f} s")
        self.client.send_motion_request(request)

    def on_placement(self, e: rp.PlacementEvent) -> None:
        if e.valid:
            say(f'placed at "{e.name}" ({e.x:.3f}, {e.y:.3f}); click to move')
        else:
            say(f'placement "{e.name}" {PLACEMENT_REFUSED}')

    def on_halted(self, e: rp.MotionHaltedEvent) -> None:
        say(f"motion halted on {e.why_halted} at ({e.x:.3f}, {e.y:.3f})")
        if e.cause_of_halt == rp.MotionHaltedEvent.HALTED_ON_COLLISION:
            self.back_off_timeout = self.client.send_timeout_request(BACK_OFF_DELAY)

    def on_timeout(self, e: rp.TimeoutEvent) -> None:
        if e.timeout_index == self.back_off_timeout:
            self.back_off_timeout = -1
            say("backing away from the wall")
            self.client.send_motion_request(
                rp.MotionRequest(-BACK_OFF_SPEED, 0.0, BACK_OFF_DISTANCE / BACK_OFF_SPEED))

    def on_head(self, e: rp.TargetSensorEvent) -> None:
        if e.status:
            say(f"head: target {e.target_name} at range {e.range:.3f} m, bearing {math.degrees(e.bearing):.1f} deg")
        else:
            say("head: no target in sight")


def say(text: str) -> None:
    print(text, flush=True)


def main(argv: Optional[List[str]] = None) -> int:
    parser = argument_parser(__doc__)
    parser.add_argument("--placement", default="home", help='placement name (default "home")')
    args = parser.parse_args(argv)
    client = connect(args, "clientzero")
    if client is None:
        return 1
    with client:
        body = build_body()
        client.send_body_specification(body)
        ClientZero(client, body).register()
        client.send_plan_request()
        client.send_placement_request(args.placement)
        try:
            client.run()
        except KeyboardInterrupt:
            say("stopped")
    return 0


if __name__ == "__main__":
    sys.exit(run_main(main))
