"""Issue 18.3: the client refuses to send NaN or an infinity, naming the argument or field, and sends
nothing; the server would drop it (docs/protocol.md section 14)."""

import math
from typing import Callable, Tuple

import pytest

import rp1client as rp
from rp1client.requests import decode_request, encode_request, read_request
from rp1client.wire import Reader, require_finite_fields
from support import ScriptedSocket

NAN = math.nan
INF = math.inf


def client() -> Tuple[rp.Client, ScriptedSocket]:
    sock = ScriptedSocket()
    return rp.Client("h", 1234).attach(sock, handshake=False), sock


def painter_with_trailer(x: float, y: float) -> rp.Painter:
    painter = rp.Painter([(0.0, 0.0), (0.1, 0.0), (0.0, 0.1)])
    painter.set_paint_color(rp.Color.RED)
    painter.set_trailer_position(x, y)
    painter.set_trailer_width(0.05)
    return painter


def actuator(value: float) -> rp.ActuatorControlRequest:
    request = rp.ActuatorControlRequest(1, rp.ActuatorControlRequest.ACTIVATE)
    request.add_parameter("left", 1.0)
    request.add_parameter("right", value)
    return request


@pytest.mark.parametrize("send, message", [
    (lambda c: c.send_timeout_request(NAN), "duration must be a finite number, got nan"),
    (lambda c: c.send_heartbeat_request(INF), "interval must be a finite number, got inf"),
    (lambda c: c.send_motion_request(rp.MotionRequest(0.5, NAN, 2.0)),
     "motion rotational velocity: nan is not a finite number"),
    (lambda c: c.send_motion_request(rp.MotionRequest(-INF, 0.0, 2.0)),
     "motion linear velocity: -inf is not a finite number"),
    (lambda c: c.send_motion_request(rp.MotionRequest(0.5, 0.0, NAN)), "motion duration: nan is not a finite number"),
    (lambda c: c.send_painter_activation_request(painter_with_trailer(0.0, NAN)),
     "painter trailer y: nan is not a finite number"),
    (lambda c: c.send_actuator_control_request(actuator(NAN)), "actuator parameter 1 value: nan is not a finite number"),
    (lambda c: c.send_request(rp.HeartbeatRequest(-INF)), "heartbeat interval: -inf is not a finite number"),
])
def test_a_non_finite_number_is_refused_naming_it_and_nothing_is_sent(send: Callable[[rp.Client], object],
                                                                        message: str) -> None:
    c, sock = client()
    with pytest.raises(ValueError) as err:
        send(c)
    assert str(err.value) == message
    assert sock.sent == []


def test_a_refused_timeout_does_not_use_up_an_index() -> None:
    c, _ = client()
    with pytest.raises(ValueError):
        c.send_timeout_request(NAN)
    assert c.send_timeout_request(1.0) == 1


def test_a_body_with_a_non_finite_dimension_is_refused_naming_the_part_and_field() -> None:
    c, sock = client()
    body = rp.Body("b")
    body.add_part(rp.Circle(0.0, 0.0, 0.15))
    body.add_part(rp.Circle(0.0, 0.0, INF))
    with pytest.raises(ValueError) as err:
        c.send_body_specification(body)
    assert str(err.value) == "body part[1].radius: inf is not a finite number"
    assert sock.sent == []


def test_finite_numbers_at_the_extremes_are_sent() -> None:
    c, sock = client()
    c.send_motion_request(rp.MotionRequest(-1.7976931348623157e308, 5e-324, 1e300))
    c.send_heartbeat_request(1e-300)
    assert len(sock.sent) == 2


def test_a_strict_reader_checks_every_f64_and_a_lenient_one_none() -> None:
    payload = encode_request(rp.TimeoutRequest(NAN, 1))
    assert math.isnan(decode_request(payload).duration), "events and test servers still read what they get"
    with pytest.raises(ValueError, match=r"^timeout duration: nan is not a finite number$"):
        require_finite_fields("", payload, read_request)
    with pytest.raises(rp.ProtocolError) as err:
        Reader(b"\x7f\xf0\x00\x00\x00\x00\x00\x00", finite=True).f64("motion duration")
    assert err.value.field == "motion duration"
