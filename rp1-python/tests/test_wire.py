"""Primitive encodings: Java's modified UTF-8, colours, counts, and round trips of whole payloads."""

import pytest

import rp1client as rp
from rp1client.wire import Reader, Writer, decode_modified_utf8, encode_modified_utf8


@pytest.mark.parametrize("text, wire", [
    ("home", "686f6d65"),
    ("a\0b", "61c08062"),
    ("\u00e9", "c3a9"),
    ("\u20ac", "e282ac"),
    ("\U0001F600", "eda0bdedb880"),
])
def test_strings_are_java_modified_utf8(text: str, wire: str) -> None:
    assert encode_modified_utf8(text).hex() == wire
    assert decode_modified_utf8(bytes.fromhex(wire), "f") == text


def test_a_lone_surrogate_survives_the_round_trip_as_in_java() -> None:
    text = "x\ud800y"
    assert decode_modified_utf8(encode_modified_utf8(text), "f") == text


def test_a_raw_zero_byte_is_read_as_nul_like_javas_read_utf() -> None:
    assert decode_modified_utf8(b"a\x00", "f") == "a\0"


@pytest.mark.parametrize("wire", ["80", "f0908080", "c3", "e282", "c341"])
def test_bytes_that_are_not_modified_utf8_name_the_field(wire: str) -> None:
    with pytest.raises(rp.ProtocolError, match=r"^placement name: invalid modified UTF-8 \(") as err:
        decode_modified_utf8(bytes.fromhex(wire), "placement name")
    assert err.value.field == "placement name" and not err.value.truncated


def test_a_string_of_65535_bytes_is_the_longest_that_can_be_sent() -> None:
    w = Writer().utf("\u00e9" * 32767 + "a")
    assert len(w.getvalue()) == 2 + 65535
    with pytest.raises(ValueError, match="string too long"):
        Writer().utf("\u00e9" * 32768)


def test_a_request_with_an_overlong_name_sends_nothing() -> None:
    from support import ScriptedSocket

    sock = ScriptedSocket()
    client = rp.Client("h", 1234).attach(sock, handshake=False)
    with pytest.raises(ValueError):
        client.send_placement_request("x" * 70000)
    client.send_halt_request()
    assert len(sock.sent) == 1, "the failed request must not reach the stream"
    assert sock.sent[0][12:16] == b"\x00\x00\x00\x01", "nor use up a sequence number"


def test_none_is_sent_as_the_empty_string() -> None:
    assert Writer().utf(None).getvalue() == b"\x00\x00"


def test_colours_are_presence_flag_and_three_components() -> None:
    w = Writer().color(rp.Color(1, 2, 3)).color(None).color_array([rp.Color.RED, None]).color_array(None)
    r = Reader(w.getvalue())
    assert (r.color("a"), r.color("b"), r.color_array("c"), r.color_array("d")) == (
        rp.Color(1, 2, 3), None, (rp.Color.RED, None), None)
    assert r.remaining == 0


def test_a_colour_component_out_of_range_names_the_component() -> None:
    data = Writer().i32(1).i32(0).i32(300).i32(0).getvalue()
    with pytest.raises(rp.ProtocolError, match=r"^fill green: 300 is outside 0\.\.255$"):
        Reader(data).color("fill")


def test_colours_are_checked_when_made() -> None:
    with pytest.raises(ValueError, match="blue"):
        rp.Color(0, 0, 256)


def test_counts_beyond_their_limit_are_refused_before_anything_is_allocated() -> None:
    data = Writer().i32(2_000_000_000).getvalue()
    with pytest.raises(rp.ProtocolError, match=r"^plan object count: 2000000000 is outside the accepted range"):
        rp.decode_plan(Writer().i32(1).utf("big").getvalue() + data)


def test_running_out_of_bytes_is_reported_as_truncation_of_the_field() -> None:
    with pytest.raises(rp.ProtocolError) as err:
        Reader(b"\x00\x00").i32("timeout index")
    assert err.value.truncated
    assert str(err.value) == "timeout index: stream ended in the middle of a message"


@pytest.mark.parametrize("request_", [
    rp.TimeoutRequest(-0.5, 3),
    rp.PlacementRequest("\U0001F600 base"),
    rp.PlacementRequest(""),
    rp.TargetSelectionRequest(True, "", False, True),
    rp.PainterChangeRequest(9, False, True, True, 0.1, -0.2, 0.3, (rp.Color.BLUE, rp.Color.GREEN)),
    rp.ActuatorControlRequest(4, 2, []),
    rp.EncoderStatusRequest(7, (), False),
])
def test_requests_survive_a_round_trip(request_: rp.Request) -> None:
    decoded = rp.decode_request(rp.encode_request(request_))
    expected = rp.PlacementRequest(None) if request_ == rp.PlacementRequest("") else request_
    assert decoded == expected


def test_a_placement_name_flag_counts_utf16_units_like_java() -> None:
    payload = rp.encode_request(rp.PlacementRequest("\U0001F600"))
    assert payload[8:12] == b"\x00\x00\x00\x02"


def test_a_plan_with_no_plan_available_is_none() -> None:
    assert rp.decode_plan(rp.encode_plan(None)) is None
    event, interlock = rp.decode_event(rp.encode_event(rp.PlanEvent(0.0, None), 4))
    assert (event, interlock) == (rp.PlanEvent(0.0, None), 4)
