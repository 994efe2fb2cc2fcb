"""Input as a stream delivers it: split anywhere, truncated, or garbage.

Whatever the server sends, the client either decodes it or raises the one ProtocolError naming the
field (docs/protocol.md section 14); it never fails with another exception and never needs one read
to hold one message.
"""

import random
from typing import List, Tuple

import pytest

import rp1client as rp
from rp1client import codes
from rp1client.messages import HEADER, read_event_message
from rp1client.wire import Reader, Writer
from support import ScriptedSocket, protocol_examples

EXAMPLES = protocol_examples()
EVENT_NAMES = sorted(n for n in EXAMPLES if n.startswith("event-"))
STREAM = b"".join(EXAMPLES[n] for n in EVENT_NAMES)
SENSOR_IDS = {rp.ContactSensorEvent: 6, rp.RangeSensorEvent: 4, rp.TargetSensorEvent: 5, rp.PaintSensorEvent: 9}
EVENT_TYPES = [rp.ContactSensorEvent, rp.MouseClickEvent, rp.PositionEvent, rp.RangeSensorEvent,
               rp.TargetSensorEvent, rp.TimeoutEvent, rp.MotionStartedEvent, rp.MotionHaltedEvent,
               rp.PlacementEvent, rp.TargetSelectionEvent, rp.PlanEvent, rp.PaintSensorEvent, rp.HeartbeatEvent,
               rp.EncoderStatusEvent]


def receive(chunks: List[bytes]) -> Tuple[List[rp.Event], ScriptedSocket]:
    """Runs a client over these chunks; returns the events its handlers saw, and the socket."""
    sock = ScriptedSocket(chunks)
    client = rp.Client("h", 1234).attach(sock, handshake=False)
    seen: List[rp.Event] = []
    for event_type in EVENT_TYPES:
        client.add_handler(event_type, seen.append, SENSOR_IDS.get(event_type))
    client.run()
    return seen, sock


def plans_as_bytes(events: List[rp.Event]) -> List[object]:
    """Plans have no equality; compare their encodings instead."""
    return [rp.encode_plan(e.plan) if isinstance(e, rp.PlanEvent) else e for e in events]


WHOLE, _ = receive([STREAM])


def test_the_whole_stream_gives_one_event_per_example() -> None:
    assert len(WHOLE) == len(EVENT_NAMES)


def test_a_stream_split_at_any_byte_gives_the_same_events() -> None:
    expected = plans_as_bytes(WHOLE)
    for cut in range(1, len(STREAM)):
        events, _ = receive([STREAM[:cut], STREAM[cut:]])
        assert plans_as_bytes(events) == expected, f"split after byte {cut}"


def test_a_stream_read_one_byte_at_a_time_gives_the_same_events() -> None:
    events, sock = receive([STREAM[i:i + 1] for i in range(len(STREAM))])
    assert plans_as_bytes(events) == plans_as_bytes(WHOLE)
    acks = [m for m in sock.sent if HEADER.unpack_from(m)[4] == codes.INTERLOCK]
    assert [m[20:] for m in acks] == [b"\x00\x00\x00\x07"]


@pytest.mark.parametrize("name", EVENT_NAMES)
def test_a_stream_that_ends_inside_an_event_names_the_missing_field(name: str) -> None:
    example = EXAMPLES[name]
    for cut in range(1, len(example)):
        with pytest.raises(rp.ProtocolError) as err:
            receive([example[:cut]])
        assert err.value.truncated and err.value.problem == "stream ended in the middle of a message"


def test_a_stream_that_ends_between_events_is_an_ordinary_end() -> None:
    closed = []
    sock = ScriptedSocket([EXAMPLES["event-timeout"]])
    client = rp.Client("h", 1234).attach(sock, handshake=False)
    client.set_shutdown_handler(lambda: closed.append(True))
    client.run()
    assert client.closed and sock.closed and closed == [True]


def _event_with_header(*header: int) -> bytes:
    return HEADER.pack(*header) + EXAMPLES["event-timeout"][20:]


@pytest.mark.parametrize("data, message", [
    (_event_with_header(1, 0, 0, 2, 3), "header version: expected 0, got 1"),
    (_event_with_header(0, 0, 9, 2, 3), "header client key: expected 0, got 9"),
    (_event_with_header(0, 4, 0, 2, 3), "header client id: expected 0, got 4"),
    (_event_with_header(0, 0, 0, 2, 9), "header transaction code: unknown code 9"),
    (_event_with_header(0, 0, 0, 2, 6), "header transaction code: a client accepts only EVENT (3), got INTERLOCK (6)"),
    (HEADER.pack(0, 0, 0, 2, 3) + Writer().i32(-1).getvalue() + bytes(40), "event code: unknown code -1"),
])
def test_a_bad_header_or_event_code_ends_the_session_with_the_field_named(data: bytes, message: str) -> None:
    sock = ScriptedSocket([data])
    client = rp.Client("h", 1234).attach(sock, handshake=False)
    with pytest.raises(rp.ProtocolError) as err:
        client.run()
    assert str(err.value) == message
    assert client.closed and sock.closed


def _body_with(part: bytes, name: str = "") -> bytes:
    return Writer().utf(name).i32(1).getvalue() + part


def _two_part_body_with_type_4() -> bytes:
    circle = Writer().i32(1).i32(codes.PART_CIRCLE).f64(0).f64(0).f64(1).utf("c")
    for _ in range(4):
        circle.i32(0)
    return Writer().utf("b").i32(2).getvalue() + circle.getvalue() + Writer().i32(2).i32(4).getvalue()


def _plan(*objects: bytes) -> bytes:
    return Writer().i32(1).utf("p").i32(len(objects)).getvalue() + b"".join(objects)


def _node(name: str) -> bytes:
    return Writer().i32(codes.PLAN_NAV_NODE).utf(name).f64(0).f64(0).utf("").i32(0).getvalue()


@pytest.mark.parametrize("decode, data, message", [
    (rp.decode_request, Writer().i32(14).i32(0).getvalue(), "request code: unknown code 14"),
    (rp.decode_body, _two_part_body_with_type_4(), "part[1].partType: type 4 (abstract BODY_SENSOR) cannot be built"),
    (rp.decode_body, _body_with(Writer().i32(1).i32(codes.PART_SHAPE).i32(-3).getvalue()),
     "part[0].outline count: -3 is outside the accepted range 0..65536"),
    (rp.decode_body, _body_with(Writer().i32(1).i32(codes.PART_SHAPE).i32(0).utf("s").i32(1).i32(300).getvalue()),
     "part[0].fillColor red: 300 is outside 0..255"),
    (rp.decode_plan, _plan(*(_node(n) for n in "abcde"), Writer().i32(codes.PLAN_NAV_LINK).utf("l").utf("x").getvalue()),
     'plan object[5] node0: no node called "x" was received before this link'),
    (rp.decode_plan, _plan(_node("a"), _node("b"), _node("a")), 'plan object[2] name: duplicate object name "a"'),
    (rp.decode_request, Writer().i32(codes.REQ_PLACEMENT).i32(0).i32(1).getvalue() + b"\x00\x01\x80",
     "placement name: invalid modified UTF-8 (malformed input around byte 0)"),
    (rp.decode_request, Writer().i32(codes.REQ_MOTION).i32(0).f64(1).f64(1).getvalue(),
     "motion duration: stream ended in the middle of a message"),
    (rp.decode_plan, _plan(_node("a")) + b"\x00", "plan: 1 bytes left over after the last object"),
])
def test_the_malformed_inputs_of_protocol_md_section_14(decode, data: bytes, message: str) -> None:
    with pytest.raises(rp.ProtocolError) as err:
        decode(data)
    assert str(err.value) == message


def _decoders():
    def event_message(data: bytes) -> object:
        return read_event_message(Reader(data), 0, 0)
    return [event_message, rp.decode_event, rp.decode_request, rp.decode_body, rp.decode_plan]


def _garbage() -> List[bytes]:
    """Random bytes, and every example with one byte replaced or cut short, from a fixed seed."""
    rng = random.Random(15)
    samples = [bytes(rng.randrange(256) for _ in range(rng.randrange(1, 120))) for _ in range(300)]
    for example in EXAMPLES.values():
        for payload in (p for p in (example, example[20:]) if p):
            for _ in range(12):
                i = rng.randrange(len(payload))
                samples.append(payload[:i] + bytes([rng.randrange(256)]) + payload[i + 1:])
                samples.append(payload[:i])
    return samples


def test_garbage_either_decodes_or_raises_the_one_exception() -> None:
    outcomes = {"decoded": 0, "refused": 0}
    for data in _garbage():
        for decode in _decoders():
            try:
                decode(data)
                outcomes["decoded"] += 1
            except rp.ProtocolError:
                outcomes["refused"] += 1
    assert outcomes["refused"] > 0 and outcomes["decoded"] > 0, outcomes


def test_a_plan_larger_than_the_receive_buffer_arrives_whole() -> None:
    plan = rp.Plan("maze")
    for i in range(2000):
        plan.add(rp.Wall(f"wall{i}", [i, 0, i + 1, 0, i + 1, 1, i, 1]))
    data = HEADER.pack(0, 0, 0, 2, codes.EVENT) + rp.encode_event(rp.PlanEvent(0.0, plan))
    assert len(data) > 2 * 65536
    events, _ = receive([data[i:i + 1000] for i in range(0, len(data), 1000)])
    assert [rp.encode_plan(e.plan) for e in events] == [rp.encode_plan(plan)]
