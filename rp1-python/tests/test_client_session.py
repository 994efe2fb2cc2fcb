"""The client's session against a scripted server: handshake, subscriptions, dispatch, interlock
acknowledgements and the event loop, compared with what the Java library sends."""

import logging
from typing import List, Tuple

import pytest

import rp1client as rp
from rp1client import codes
from rp1client.messages import HEADER
from support import ScriptedSocket, protocol_examples

EXAMPLES = protocol_examples()


def event(e: rp.Event, interlock: int = 0, client_id: int = 0, key: int = 0) -> bytes:
    return HEADER.pack(0, client_id, key, 1, codes.EVENT) + rp.encode_event(e, interlock)


def connected(*incoming: bytes, accept: bytes = EXAMPLES["accept"]) -> Tuple[rp.Client, ScriptedSocket]:
    sock = ScriptedSocket([accept, *incoming])
    return rp.Client("h", 1234).attach(sock), sock


def sent(sock: ScriptedSocket) -> List[object]:
    """What the client sent after the handshake: requests decoded, other messages as (code, payload)."""
    out: List[object] = []
    for message in sock.sent[1:]:
        code = HEADER.unpack_from(message)[4]
        out.append(rp.decode_request(message[20:]) if code == codes.REQUEST else (code, message[20:]))
    return out


def sequences(sock: ScriptedSocket) -> List[int]:
    return [HEADER.unpack_from(m)[3] for m in sock.sent]


def ack(number: int) -> Tuple[int, bytes]:
    return codes.INTERLOCK, number.to_bytes(4, "big")


def subscription(code: int, index: int, enable: bool) -> rp.SubscriptionRequest:
    return rp.SubscriptionRequest(code, index, enable)


def range_sensor() -> rp.RangeSensor:
    return rp.RangeSensor([(0, 0), (0.1, 0), (0, 0.1)], 0.1, 0, 0, 1.0, 4)


def test_connect_carries_sequence_0_and_the_next_message_2() -> None:
    client, sock = connected()
    client.send_halt_request()
    client.send_halt_request()
    assert sequences(sock) == [0, 2, 3]


def test_the_client_adopts_the_id_and_key_of_the_accept() -> None:
    accept = HEADER.pack(0, 5, 9, 1, codes.ACCEPT)
    client, sock = connected(event(rp.TimeoutEvent(1.0, 1), 3, client_id=5, key=9), accept=accept)
    client.run()
    assert [HEADER.unpack_from(m)[1:3] for m in sock.sent] == [(0, 0), (5, 9)]


def test_an_answer_that_is_not_accept_fails_the_handshake() -> None:
    with pytest.raises(rp.ProtocolError, match=r"^ACCEPT transaction code: expected ACCEPT \(2\), got EVENT \(3\)$"):
        connected(accept=HEADER.pack(0, 0, 0, 1, codes.EVENT))


def test_the_first_handler_of_a_simulation_event_subscribes_and_later_ones_do_not() -> None:
    client, sock = connected()
    sonar = range_sensor()
    client.add_handler(rp.MotionHaltedEvent, print)
    client.add_handler(rp.MotionHaltedEvent, repr)
    client.add_handler(rp.RangeSensorEvent, print, sonar)
    client.add_handler(rp.RangeSensorEvent, repr, sonar)
    client.add_handler(rp.TimeoutEvent, print)
    client.add_handler(rp.PlanEvent, print)
    assert sent(sock) == [subscription(codes.EVT_MOTION_HALTED, 0, True),
                          subscription(codes.EVT_RANGE_SENSOR, sonar.id, True)]


def test_every_removal_unsubscribes_even_while_handlers_remain() -> None:
    client, sock = connected()
    client.add_handler(rp.MouseClickEvent, print)
    client.add_handler(rp.MouseClickEvent, repr)
    client.remove_handler(rp.MouseClickEvent, print)
    client.remove_handler(rp.MouseClickEvent, repr)
    client.remove_handler(rp.TimeoutEvent, print)
    assert sent(sock) == [subscription(codes.EVT_MOUSE_CLICK, 0, True), subscription(codes.EVT_MOUSE_CLICK, 0, False),
                          subscription(codes.EVT_MOUSE_CLICK, 0, False)]


def test_removing_every_handler_stops_the_events_and_a_new_handler_subscribes_again() -> None:
    client, sock = connected(event(rp.MouseClickEvent(1.0, 0, 1, 0.5, 0.5)))
    removed: List[rp.Event] = []
    kept: List[rp.Event] = []
    client.add_handler(rp.MouseClickEvent, removed.append)
    client.add_handler(rp.MouseClickEvent, removed.append)
    client.remove_handlers(rp.MouseClickEvent)
    client.add_handler(rp.MouseClickEvent, kept.append)
    client.run()
    assert sent(sock) == [subscription(codes.EVT_MOUSE_CLICK, 0, True), subscription(codes.EVT_MOUSE_CLICK, 0, False),
                          subscription(codes.EVT_MOUSE_CLICK, 0, True)]
    assert removed == [] and len(kept) == 1


def test_a_handler_added_twice_is_gone_after_one_removal() -> None:
    client, sock = connected(event(rp.TimeoutEvent(1.0, 7)))
    removed: List[rp.Event] = []
    kept: List[rp.Event] = []
    client.add_handler(rp.TimeoutEvent, removed.append)
    client.add_handler(rp.TimeoutEvent, removed.append)
    client.add_handler(rp.TimeoutEvent, kept.append)
    client.remove_handler(rp.TimeoutEvent, removed.append)
    client.run()
    assert removed == [] and len(kept) == 1


def test_handlers_added_before_connecting_never_subscribe() -> None:
    client = rp.Client("h", 1234)
    client.add_handler(rp.MotionStartedEvent, print)
    sock = ScriptedSocket([EXAMPLES["accept"]])
    client.attach(sock)
    client.add_handler(rp.MotionStartedEvent, repr)
    assert sent(sock) == []


def test_sensor_events_go_to_the_handlers_of_their_sensor_only() -> None:
    first, second = range_sensor(), range_sensor()
    reading = rp.RangeSensorEvent(2.0, second.id, 1.0, 1.0, True, 0.0, 0.0, 0.5, "wall")
    client, _ = connected(event(reading))
    seen: List[Tuple[str, rp.Event]] = []
    client.add_handler(rp.RangeSensorEvent, lambda e: seen.append(("first", e)), first)
    client.add_handler(rp.RangeSensorEvent, lambda e: seen.append(("second", e)), second)
    client.run()
    assert seen == [("second", reading)]


def test_a_sensor_of_the_wrong_kind_is_refused() -> None:
    client, _ = connected()
    with pytest.raises(TypeError, match="RangeSensor"):
        client.add_handler(rp.RangeSensorEvent, print, rp.ContactSensor([(0, 0), (1, 0), (0, 1)]))
    with pytest.raises(TypeError, match="pass it"):
        client.add_handler(rp.ContactSensorEvent, print)


def test_an_interlocked_event_is_acknowledged_after_its_handlers() -> None:
    client, sock = connected(event(rp.TimeoutEvent(1.0, 1), 11))
    client.add_handler(rp.TimeoutEvent, lambda e: client.send_timeout_request(0.5))
    client.run()
    assert sent(sock) == [rp.TimeoutRequest(0.5, 1), ack(11)]


def test_an_interlocked_event_without_handlers_is_acknowledged_too() -> None:
    client, sock = connected(event(rp.HeartbeatEvent(1.0, 1), 5), event(rp.HeartbeatEvent(2.0, 2), 0))
    client.run()
    assert sent(sock) == [ack(5)]


def test_a_failing_handler_is_logged_and_the_rest_still_run(caplog: pytest.LogCaptureFixture) -> None:
    client, sock = connected(event(rp.TimeoutEvent(1.0, 1), 2))
    calls: List[str] = []

    def broken(e: rp.Event) -> None:
        raise RuntimeError("broken handler")

    client.add_handler(rp.TimeoutEvent, broken)
    client.add_handler(rp.TimeoutEvent, lambda e: calls.append("second"))
    with caplog.at_level(logging.ERROR, logger="rp1client"):
        client.run()
    assert calls == ["second"] and sent(sock) == [ack(2)]
    assert "broken handler" in caplog.text


def test_a_consumed_event_reaches_no_further_handler() -> None:
    client, _ = connected(event(rp.TimeoutEvent(1.0, 1)))
    calls: List[str] = []
    client.add_handler(rp.TimeoutEvent, lambda e: (calls.append("first"), e.consume()))
    client.add_handler(rp.TimeoutEvent, lambda e: calls.append("second"))
    client.run()
    assert calls == ["first"]


def test_run_until_returns_after_the_first_event_at_that_time_and_run_continues_later() -> None:
    client, sock = connected(*(event(rp.HeartbeatEvent(float(t), t), 100 + t) for t in range(1, 5)))
    beats: List[int] = []
    client.add_handler(rp.HeartbeatEvent, lambda e: beats.append(e.sequence))
    client.run(until=2.0)
    assert beats == [1, 2] and client.sim_time == 2.0 and not client.closed
    assert sent(sock) == [ack(101), ack(102)], "the event that ends the run is acknowledged"
    client.run()
    assert beats == [1, 2, 3, 4] and client.closed


def test_stop_from_a_handler_ends_run_after_that_event() -> None:
    client, _ = connected(*(event(rp.HeartbeatEvent(float(t), t)) for t in range(1, 4)))
    beats: List[int] = []

    def beat(e: rp.HeartbeatEvent) -> None:
        beats.append(e.sequence)
        if e.sequence == 2:
            client.stop()

    client.add_handler(rp.HeartbeatEvent, beat)
    client.run()
    assert beats == [1, 2] and not client.closed


def test_requests_after_the_session_ended_are_dropped() -> None:
    client, sock = connected()
    client.close()
    client.send_halt_request()
    client.add_handler(rp.MouseClickEvent, print)
    assert sent(sock) == [] and sock.closed


def test_sending_before_connecting_is_a_mistake() -> None:
    with pytest.raises(RuntimeError, match="connect"):
        rp.Client("h", 1234).send_halt_request()


def test_a_painter_without_trailer_or_colour_is_switched_off_instead() -> None:
    client, sock = connected()
    painter = rp.Painter()
    painter.set_paint_color(rp.Color.RED)
    client.send_painter_activation_request(painter)
    painter.set_trailer_width(0.01)
    painter.set_paint_color(None)
    client.send_painter_activation_request(painter)
    assert sent(sock) == [rp.PainterChangeRequest(painter.id)] * 2 and not painter.active


def test_actuator_commands_without_parameters() -> None:
    client, sock = connected()
    steering = rp.DifferentialSteering(0.2, 0.05)
    client.send_actuator_control_request(steering.get_control_request_for_wheel_rotation(0.0, 0.0))
    client.send_actuator_control_request(rp.ActuatorControlRequest(steering.id, rp.ActuatorControlRequest.RESET))
    assert sent(sock) == [rp.HaltRequest()]


def test_timeouts_and_encoder_requests_are_numbered_separately() -> None:
    client, sock = connected()
    steering = rp.DifferentialSteering(0.2, 0.05)
    steering.add_default_wheels(0.05, 0.02)
    left, right = steering.add_encoders_to_default_wheels(32)
    assert [client.send_timeout_request(1.0), client.send_timeout_request(1.0)] == [1, 2]
    assert client.send_encoder_status_request(left) == 1
    assert client.send_encoder_status_request([left, None]) == -1
    assert client.send_encoder_status_request([left, right], True) == 2
    assert sent(sock)[2:] == [rp.EncoderStatusRequest(1, (left.id,), False),
                              rp.EncoderStatusRequest(2, (left.id, right.id), True)]


def test_target_selection_methods_set_the_flags_as_the_java_library() -> None:
    client, sock = connected()
    client.send_target_selection_request("goal", False)
    client.send_random_target_selection_request(True)
    client.send_exclusive_random_target_selection_request()
    client.send_all_targets_selection_request(False)
    assert sent(sock) == [rp.TargetSelectionRequest(False, "goal", False, False),
                          rp.TargetSelectionRequest(True, "", True, False),
                          rp.TargetSelectionRequest(True, "", True, True),
                          rp.TargetSelectionRequest(False, "*", False, False)]


def test_settings_come_from_rossum_ini(tmp_path, monkeypatch: pytest.MonkeyPatch) -> None:
    (tmp_path / "rossum.ini").write_text("# where the server is\nhostName = robots.local  # comment\nport: 7800\n")
    monkeypatch.chdir(tmp_path)
    client = rp.Client()
    assert (client.host, client.port) == ("robots.local", 7800)
    assert rp.Client(port=7900).host == "robots.local"


def test_a_bad_port_in_rossum_ini_names_key_value_and_file(tmp_path) -> None:
    path = tmp_path / "rossum.ini"
    path.write_text("port=65536\n")
    with pytest.raises(rp.SettingsError, match=r"port number 65536 not in valid range \[1,65535\] \(.*rossum.ini\)"):
        rp.ClientSettings.load(str(path))


def test_close_from_another_thread_ends_a_waiting_run() -> None:
    import socket
    import threading

    ours, theirs = socket.socketpair()
    client = rp.Client("h", 1234).attach(ours, handshake=False)
    loop = threading.Thread(target=client.run)
    loop.start()
    client.close()
    loop.join(5.0)
    assert not loop.is_alive() and client.closed
    theirs.close()
