"""Every worked example of docs/protocol.md, byte for byte.

Frames the client sends are produced by replaying the document's imaginary session through a real
``Client`` (handshake, body as message 2, one request of each kind as messages 3 to 19, then the
acknowledgement of an interlocked event as message 20) and compared with the examples. Frames the
client receives are decoded as the client decodes them and compared with the values the document
describes, then encoded again. Requests are also decoded as a server would, and bodies and the plan
decoded and encoded again.
"""

import functools
import math
from typing import Callable, Dict, List, Tuple

import pytest

import rp1client as rp
from rp1client import codes
from rp1client.messages import HEADER, read_accept, read_event_message
from rp1client.wire import Reader
from support import ScriptedSocket, protocol_examples

EXAMPLES = protocol_examples()


def test_the_document_has_examples_to_check() -> None:
    assert len(EXAMPLES) >= 38, f"only {len(EXAMPLES)} examples found in docs/protocol.md"


# --------------------------------------------------------------------------------------------
# What the client sends

def _session_parts() -> Tuple[rp.DifferentialSteering, rp.TargetSensor, rp.Painter]:
    """The parts the example requests refer to: wheel system 1 with wheels 2 and 3, target sensor
    5, painter 7."""
    rp.set_next_part_id(1)
    steering = rp.DifferentialSteering(0.4, 0.05)
    steering.add_default_wheels(0.05, 0.02)
    rp.set_next_part_id(5)
    sensor = rp.TargetSensor([(0, 0), (0.1, 0), (0, 0.1)], 0.1, 0.0, 0.0, 1.0, 1.0, 3, 3)
    rp.set_next_part_id(7)
    painter = rp.Painter()
    painter.set_trailer_position(-0.25, 0.0)
    painter.set_trailer_width(0.0625)
    painter.set_paint_color(rp.Color.RED)
    return steering, sensor, painter


def _connected(sock: ScriptedSocket) -> rp.Client:
    sock.feed(EXAMPLES["accept"])
    return rp.Client("example", 7758).attach(sock)


@functools.lru_cache(maxsize=None)
def replay_imaginary_session() -> Dict[str, bytes]:
    """The messages a client sends in the document's session, by example name."""
    steering, sensor, painter = _session_parts()
    sock = ScriptedSocket()
    client = _connected(sock)
    client.send_body_specification(body_circle())
    steps: List[Tuple[str, Callable[[], object]]] = [
        ("request-timeout", lambda: client.send_timeout_request(1.5)),
        ("request-subscription", lambda: client.add_handler(rp.TargetSensorEvent, lambda e: None, sensor)),
        ("request-sensor-status", lambda: client.send_sensor_status_request(sensor)),
        ("request-motion", lambda: client.send_motion_request(rp.MotionRequest(0.5, 0.25, 2.0))),
        ("request-halt", client.send_halt_request),
        ("request-position", client.send_position_request),
        ("request-set-position", lambda: client.send_request(rp.SetPositionRequest())),
        ("request-placement", lambda: client.send_placement_request("home")),
        ("request-placement-any", client.send_placement_request),
        ("request-target-selection", lambda: client.send_exclusive_target_selection_request("candle")),
        ("request-plan", client.send_plan_request),
        ("request-heartbeat", lambda: client.send_heartbeat_request(0.5)),
        ("request-painter-activation", lambda: client.send_painter_activation_request(painter)),
        ("request-painter-deactivation", lambda: client.send_painter_deactivation_request(painter)),
        ("request-painter-erasure", lambda: client.send_painter_erasure_request(painter)),
        ("request-actuator-control",
         lambda: client.send_actuator_control_request(steering.get_control_request_for_wheel_rotation(2.0, 4.0))),
        ("request-encoder-status",
         lambda: client.send_encoder_status_request([steering.left_wheel, steering.right_wheel], True)),
    ]
    for _, step in steps:
        step()
    sock.feed(EXAMPLES["event-timeout-interlocked"])
    client.run()
    names = ["connect", "body-circle"] + [name for name, _ in steps] + ["interlock-ack"]
    assert len(sock.sent) == len(names), "one message per step, and one acknowledgement"
    return dict(zip(names, sock.sent))


# --------------------------------------------------------------------------------------------
# Bodies

def body_circle() -> rp.Body:
    rp.set_next_part_id(1)
    circle = rp.Circle(0.0, 0.0, 0.15)
    circle.name = "c"
    circle.fill_color = rp.Color.WHITE
    circle.line_color = None
    body = rp.Body("B")
    body.add_part(circle)
    return body


def body_differential() -> rp.Body:
    rp.set_next_part_id(1)
    steering = rp.DifferentialSteering(0.4, 0.05)
    steering.add_default_wheels(0.05, 0.02)
    steering.add_encoders_to_default_wheels(64)
    body = rp.Body("W")
    body.add_part(steering)
    return body


def body_range_sensor() -> rp.Body:
    rp.set_next_part_id(4)
    sonar = rp.RangeSensor([(0.0, -0.05), (0.1, 0.0), (0.0, 0.05)], 0.1, 0.0, 0.0, 2.0, 8)
    sonar.name = "sonar"
    body = rp.Body("R")
    body.add_part(sonar)
    return body


BODIES = {"body-circle": body_circle, "body-differential": body_differential, "body-range-sensor": body_range_sensor}


# --------------------------------------------------------------------------------------------
# What the client receives, and what a server decodes

REQUESTS = {
    "request-timeout": rp.TimeoutRequest(1.5, 1),
    "request-subscription": rp.SubscriptionRequest(codes.EVT_TARGET_SENSOR, 5, True),
    "request-sensor-status": rp.SensorStatusRequest(5),
    "request-motion": rp.MotionRequest(0.5, 0.25, 2.0),
    "request-halt": rp.HaltRequest(),
    "request-position": rp.PositionRequest(),
    "request-set-position": rp.SetPositionRequest(),
    "request-placement": rp.PlacementRequest("home"),
    "request-placement-any": rp.PlacementRequest(None),
    "request-target-selection": rp.TargetSelectionRequest(False, "candle", True, True),
    "request-plan": rp.PlanRequest(),
    "request-heartbeat": rp.HeartbeatRequest(0.5),
    "request-painter-activation": rp.PainterChangeRequest(7, False, True, True, -0.25, 0.0, 0.0625, (rp.Color.RED,)),
    "request-painter-deactivation": rp.PainterChangeRequest(7),
    "request-painter-erasure": rp.PainterChangeRequest(7, erasure=True),
    "request-actuator-control": rp.ActuatorControlRequest(
        1, 3, [("leftRotationalVelocity", 2.0), ("rightRotationalVelocity", 4.0)]),
    "request-encoder-status": rp.EncoderStatusRequest(1, (2, 3), True),
}

EVENTS = {
    "event-contact-sensor": (rp.ContactSensorEvent(3.25, 6, True, "north"), 0),
    "event-mouse-click": (rp.MouseClickEvent(4.0, 1, 2, 1.5, 2.25), 0),
    "event-position": (rp.PositionEvent(5.0, 1.0, 2.0, 0.5, 0.25, -0.125), 0),
    "event-range-sensor": (rp.RangeSensorEvent(5.5, 4, 1.0, 2.0, True, 0.0, 0.0, 0.75, "north"), 0),
    "event-target-sensor": (rp.TargetSensorEvent(6.0, 5, 1.0, 2.0, True, 1.0, 0.0, 1.5, 0.0, 1.5, 0.0, "candle"), 0),
    "event-timeout": (rp.TimeoutEvent(2.5, 1), 0),
    "event-motion-started": (rp.MotionStartedEvent(6.5, 0.5, 0.25, 2.0, 1.0, 2.0, 0.5), 0),
    "event-motion-halted": (rp.MotionHaltedEvent(8.5, 2, 1.75, 2.5, 1.0, 2.0), 0),
    "event-placement": (rp.PlacementEvent(1.25, True, "home", 2.5, 2.5, math.radians(225)), 0),
    "event-target-selection": (rp.TargetSelectionEvent(9.0, False, "candle"), 0),
    "event-paint-sensor": (rp.PaintSensorEvent(10.0, 9, 0.5, 0.125, True, 3), 0),
    "event-heartbeat": (rp.HeartbeatEvent(10.5, 3), 0),
    "event-encoder-status": (rp.EncoderStatusEvent(11.0, 1, 2, 5, 7, 1, 5, 1.5, True), 0),
    "event-timeout-interlocked": (rp.TimeoutEvent(3.0, 2), 7),
}


def demo_plan() -> rp.Plan:
    """The plan "demo" of section 9."""
    plan = rp.Plan("demo")
    plan.add(rp.Wall("north", [0, 2, 2, 2, 2, 2.5, 0, 2.5]))
    plan.add(rp.Target("candle", [1.5, 1.0, 0.125]))
    plan.add(rp.Placement("home", [0.5, 0.5, 0.0, 0.25]))
    a = rp.NavNode("a", 0.5, 1.5, None, rp.Color.CYAN)
    b = rp.NavNode("b", 1.5, 1.5, "B", rp.Color.CYAN)
    plan.add(a)
    plan.add(b)
    plan.add(rp.NavLink("ab", a, b, None, rp.Color.CYAN))
    plan.add(rp.Paint("stripe", [0, 0, 1, 0, 1, 0.25, 0, 0.25, 0, 0], rp.Color.YELLOW))
    return plan


def _header(example: bytes) -> Tuple[int, ...]:
    return HEADER.unpack_from(example)


# --------------------------------------------------------------------------------------------
# The checks, one per example

def check_sent(name: str, example: bytes) -> None:
    assert replay_imaginary_session()[name].hex() == example.hex()


def check_request(name: str, example: bytes) -> None:
    if name != "request-set-position":
        check_sent(name, example)
    assert _header(example)[4] == codes.REQUEST
    assert rp.decode_request(example[HEADER.size:]) == REQUESTS[name]


def check_event(name: str, example: bytes) -> None:
    expected, interlock = EVENTS[name]
    event, got_interlock, sequence = read_event_message(Reader(example), 0, 0)
    assert (event, got_interlock) == (expected, interlock)
    again = HEADER.pack(0, 0, 0, sequence, codes.EVENT) + rp.encode_event(event, got_interlock)
    assert again.hex() == example.hex()


def check_body(name: str, example: bytes) -> None:
    if name == "body-circle":
        check_sent(name, example)
    payload = example[HEADER.size:]
    assert rp.encode_body(BODIES[name]()).hex() == payload.hex()
    before = rp.next_part_id()
    assert rp.encode_body(rp.decode_body(payload)) == payload
    assert rp.next_part_id() == before, "decoding leaves the part-id counter alone"


def check_plan(name: str, example: bytes) -> None:
    event, interlock, sequence = read_event_message(Reader(example), 0, 0)
    plan = event.plan
    assert (event.sim_time, interlock, plan.caption, len(plan)) == (0.0, 0, "demo", 7)
    assert plan["north"].vertices == ((0, 2), (2, 2), (2, 2.5), (0, 2.5))
    assert (plan["candle"].x, plan["candle"].y, plan["candle"].radius) == (1.5, 1.0, 0.125)
    assert (plan["home"].x, plan["home"].orientation, plan["home"].radius) == (0.5, 0.0, 0.25)
    assert (plan["b"].x, plan["b"].y, plan["b"].label, plan["b"].line_color) == (1.5, 1.5, "B", rp.Color.CYAN)
    assert (plan["ab"].node0, plan["ab"].node1) == (plan["a"], plan["b"]) and plan["a"].links == [plan["ab"]]
    assert plan["stripe"].vertices == ((0, 0), (1, 0), (1, 0.25), (0, 0.25))
    assert plan["stripe"].fill_color == rp.Color.YELLOW
    expected = HEADER.pack(0, 0, 0, sequence, codes.EVENT) + rp.encode_event(rp.PlanEvent(0.0, demo_plan()))
    assert expected.hex() == example.hex()


def check_connect(name: str, example: bytes) -> None:
    check_sent(name, example)


def check_accept(name: str, example: bytes) -> None:
    assert read_accept(Reader(example)) == (0, 0, 1)


def check_interlock_ack(name: str, example: bytes) -> None:
    check_sent(name, example)
    assert _header(example)[3:] == (20, codes.INTERLOCK)


CHECKS: Dict[str, Callable[[str, bytes], None]] = {
    "connect": check_connect, "accept": check_accept, "event-plan": check_plan, "interlock-ack": check_interlock_ack,
    **{name: check_request for name in REQUESTS}, **{name: check_event for name in EVENTS},
    **{name: check_body for name in BODIES}}


@pytest.mark.parametrize("name", sorted(EXAMPLES))
def test_protocol_example(name: str) -> None:
    check = CHECKS.get(name)
    assert check is not None, f"docs/protocol.md has an example {name!r} that no test checks"
    check(name, EXAMPLES[name])


def test_every_check_has_its_example_in_the_document() -> None:
    assert sorted(set(CHECKS) - set(EXAMPLES)) == []
