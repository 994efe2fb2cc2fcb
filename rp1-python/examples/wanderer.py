#!/usr/bin/env python3
"""Wanderer: a round robot that drives about and turns away from walls.

It drives straight ahead; when its range sensor reads a wall closer than 0.3 m it turns on the
spot, and when it bumps into something (its motion halts in a collision) it backs off and turns.
A motion that cannot start at all (the way is blocked) is followed by a try in another direction.
Once per simulated second it prints where it is::

    position t=<sim time> x=<m> y=<m> heading=<rad>

and ``--duration`` simulated seconds after it was placed it disconnects and exits with status 0 (1
if it could not connect or be placed, 2 if the simulator went away first). The seconds count from
the placement, not from 0: a paced simulator's clock runs from its start, robots or not.

    python wanderer.py --host 127.0.0.1 --port 7758 --duration 30
"""

import math
import sys
from typing import Callable, List, Optional

import rp1client as rp
from connection import PLACEMENT_REFUSED, argument_parser, connect, run_main

SPEED = 0.25
CLOSE = 0.3
TURN_RATE = math.pi / 2
TURN_TIME = 0.75
BACK_SPEED = 0.1
BACK_TIME = 1.0
#: How many motions in a row may be blocked before the robot waits a moment.
MAX_BLOCKED = 8


def build_body() -> rp.Body:
    """A 0.2 m round robot with a bumper on its front half and a 1 m range sensor looking ahead.
    The bumper and sensor lie within the chassis circle, so turning on the spot sweeps no more."""
    body = rp.Body("Wanderer")
    steering = rp.DifferentialSteering(0.16, 0.03)
    steering.add_default_wheels(0.03, 0.02)
    steering.set_color(rp.Color.DARK_GRAY)
    chassis = rp.Circle(0.0, 0.0, 0.1)
    chassis.name = "chassis"
    arc = [math.radians(a) for a in range(-60, 61, 10)]
    bumper = rp.ContactSensor([(0.1 * math.cos(a), 0.1 * math.sin(a)) for a in arc]
                              + [(0.085 * math.cos(a), 0.085 * math.sin(a)) for a in reversed(arc)])
    bumper.name = "bumper"
    sonar = rp.RangeSensor([(0.06, -0.02), (0.09, 0.0), (0.06, 0.02)], 0.09, 0.0, 0.0, 1.0, 20)
    sonar.name = "sonar"
    for part in (chassis, bumper, sonar, steering):
        body.add_part(part)
    return body


class Wanderer:
    """The robot's logic: a small state machine driven by the simulator's events."""

    def __init__(self, client: rp.Client, body: rp.Body, duration: float) -> None:
        self.client = client
        self.sonar = body.part_by_name("sonar")
        self.bumper = body.part_by_name("bumper")
        self.duration = duration
        self.state = "idle"
        self.blocked = 0
        self.placed: Optional[bool] = None
        #: The simulated time the robot was placed at, from which --duration counts.
        self.placed_at: Optional[float] = None

    def register(self) -> None:
        c = self.client
        c.add_handler(rp.PlacementEvent, self.on_placement)
        c.add_handler(rp.HeartbeatEvent, lambda e: c.send_position_request())
        c.add_handler(rp.PositionEvent, self.on_position)
        c.add_handler(rp.RangeSensorEvent, self.on_range, self.sonar)
        c.add_handler(rp.ContactSensorEvent, self.on_contact, self.bumper)
        c.add_handler(rp.MotionHaltedEvent, self.on_halted)
        c.add_handler(rp.TimeoutEvent, lambda e: self.drive())

    def move(self, state: str, v: float, w: float, t: float) -> None:
        self.state = state
        self.client.send_motion_request(rp.MotionRequest(v, w, t))

    def drive(self) -> None:
        self.move("driving", SPEED, 0.0, 1000.0)
        self.client.send_sensor_status_request(self.sonar)

    def turn(self, direction: float = 1.0) -> None:
        self.move("turning", 0.0, direction * TURN_RATE, TURN_TIME)

    def back_off(self) -> None:
        self.move("backing", -BACK_SPEED, 0.0, BACK_TIME)

    def on_placement(self, e: rp.PlacementEvent) -> None:
        self.placed = e.valid
        self.placed_at = e.sim_time
        if not e.valid:
            print(f"wanderer: placement {e.name!r} {PLACEMENT_REFUSED}", file=sys.stderr)
            self.client.stop()
            return
        self.client.send_heartbeat_request(1.0)
        self.drive()

    def on_position(self, e: rp.PositionEvent) -> None:
        print(f"position t={e.sim_time:.3f} x={e.x:.3f} y={e.y:.3f} heading={e.orientation:.3f}", flush=True)
        if self.placed_at is not None and e.sim_time >= self.placed_at + self.duration:
            self.client.stop()

    def on_range(self, e: rp.RangeSensorEvent) -> None:
        if self.state == "driving" and e.status and e.range < CLOSE:
            self.turn()

    def on_contact(self, e: rp.ContactSensorEvent) -> None:
        if e.status:
            print(f"bump into {e.object_name or 'another robot'} at t={e.sim_time:.3f}", file=sys.stderr)

    def on_halted(self, e: rp.MotionHaltedEvent) -> None:
        if e.duration < 1e-3:
            self.try_another_way_out()
            return
        self.blocked = 0
        if e.cause_of_halt == rp.MotionHaltedEvent.HALTED_ON_COLLISION:
            self.turn() if self.state == "backing" else self.back_off()
        elif e.cause_of_halt == rp.MotionHaltedEvent.HALTED_ON_COMPLETION:
            if self.state == "backing":
                self.turn()
            elif self.state == "turning":
                self.drive()

    def try_another_way_out(self) -> None:
        """A motion that ended before it could move: the way is blocked, so the next try goes
        another way. After many tries the robot waits half a second and drives again."""
        self.blocked += 1
        if self.blocked >= MAX_BLOCKED:
            self.blocked = 0
            self.state = "waiting"
            self.client.send_timeout_request(0.5)
            return
        ways_out: List[Callable[[], None]] = [self.back_off, lambda: self.turn(-1.0), self.turn, self.drive]
        ways_out[(self.blocked - 1) % len(ways_out)]()

def main(argv: Optional[List[str]] = None) -> int:
    parser = argument_parser(__doc__)
    parser.add_argument("--duration", type=float, default=60.0, help="simulated seconds to wander (default 60)")
    parser.add_argument("--placement", default="", help="placement name (default: any placement of the plan)")
    args = parser.parse_args(argv)
    client = connect(args, "wanderer")
    if client is None:
        return 1
    with client:
        body = build_body()
        client.send_body_specification(body)
        wanderer = Wanderer(client, body, args.duration)
        wanderer.register()
        client.send_placement_request(args.placement)
        client.run()
        if wanderer.placed is False:
            return 1
        if client.closed:
            print("wanderer: the simulator closed the connection", file=sys.stderr)
            return 2
    return 0


if __name__ == "__main__":
    sys.exit(run_main(main))
