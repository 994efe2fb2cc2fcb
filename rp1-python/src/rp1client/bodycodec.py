"""The payload of a BODY_SPECIFICATION message (docs/protocol.md section 8).

Each part is sent as its id, its type, its type's fields, its name and four colours. Decoding gives
each part the id on the wire, and the wheels of a wheel system the ids following the system's, without
touching this process's part-id counter.
"""

from typing import Any, Callable, Dict, Tuple, Union

from . import codes
from .body import (Body, BodyPart, Circle, ContactSensor, PaintSensor, Painter, RangeSensor, Shape, TargetSensor,
                   _ids)
from .errors import ProtocolError
from .steering import AckermanSteering, Caster, DifferentialSteering, Wheel, WheelSystem
from .wire import Reader, Writer, read_exactly, require_finite_fields

_DIFFERENTIAL = 0
_ACKERMAN = 1
_PLAIN_WHEEL = 0
_CASTER = 1


def encode_body(body: Body, check_finite: bool = False) -> bytes:
    """The payload (everything after the header) of a body specification.

    Raises:
        ValueError: if the body has no part the protocol can carry, or a name is too long, or, with
            ``check_finite``, if a dimension is NaN or infinite (naming the part and field).
    """
    w = Writer()
    write_body(w, body)
    payload = w.getvalue()
    if check_finite and not w.finite:
        require_finite_fields("body ", payload, read_body)
    return payload


def write_body(w: Writer, body: Body) -> None:
    """Appends a body specification's payload; parts of no wire type are left out."""
    parts = [p for p in body.parts if p.wire_type != codes.PART_UNDEFINED]
    if not parts:
        raise ValueError(f"body {body.name!r} has no part that can be sent to the simulator")
    w.utf(body.name).i32(len(parts))
    for part in parts:
        w.i32(part.id).i32(part.wire_type)
        _WRITERS[part.wire_type](w, part)
        w.utf(part.name)
        for color in (part.fill_color, part.line_color, part.hot_fill_color, part.hot_line_color):
            w.color(color)


def _write_detector(w: Writer, part: Union[TargetSensor, RangeSensor, PaintSensor]) -> None:
    w.points(part.outline).f64(part.x_detector).f64(part.y_detector)


def _write_target_sensor(w: Writer, s: TargetSensor) -> None:
    _write_detector(w, s)
    w.f64(s.sight_angle).f64(s.width).f64(s.max_range).i32(s.n_width_bin).i32(s.n_range_bin)


def _write_range_sensor(w: Writer, s: RangeSensor) -> None:
    _write_detector(w, s)
    w.f64(s.sight_angle).f64(s.max_range).i32(s.n_range_bin)


def _write_paint_sensor(w: Writer, s: PaintSensor) -> None:
    _write_detector(w, s)
    regions = s.region_sensitivity or ()
    w.i32(len(regions))
    for region in regions:
        w.i32(region)


def _write_wheel_system(w: Writer, system: WheelSystem) -> None:
    if isinstance(system, AckermanSteering):
        w.i32(_ACKERMAN).f64(system.track_width).f64(system.wheel_base).f64(system.drive_wheel_radius)
        w.f64(system.max_abs_steering_angle).boolean(system.dual_steering)
    else:
        w.i32(_DIFFERENTIAL).f64(system.track_width).f64(system.drive_wheel_radius)
    w.i32(len(system.wheels))
    for wheel in system.wheels:
        w.i32(_CASTER if wheel.is_caster else _PLAIN_WHEEL).points(wheel.outline)
        w.f64(wheel.x).f64(wheel.y).f64(wheel.radius).f64(wheel.max_abs_steering_angle)
        w.i32(wheel.encoder_interval_count)


_WRITERS: Dict[int, Callable[[Writer, Any], object]] = {
    codes.PART_CIRCLE: lambda w, c: w.f64(c.x).f64(c.y).f64(c.radius),
    codes.PART_SHAPE: lambda w, s: w.points(s.outline),
    codes.PART_CONTACT_SENSOR: lambda w, s: w.points(s.outline),
    codes.PART_PAINTER: lambda w, s: w.points(s.outline),
    codes.PART_TARGET_SENSOR: _write_target_sensor,
    codes.PART_RANGE_SENSOR: _write_range_sensor,
    codes.PART_PAINT_SENSOR: _write_paint_sensor,
    codes.PART_WHEEL_SYSTEM: _write_wheel_system,
}


def decode_body(data: bytes) -> Body:
    """Decodes a body specification's payload, which must hold exactly one body.

    Raises:
        ProtocolError: naming the field, if the bytes are malformed or truncated.
    """
    return read_exactly(data, read_body, "body", "the last part")


def read_body(r: Reader) -> Body:
    """Reads a body specification's payload; empty slots and undefined parts are skipped."""
    body = Body(r.utf("bodyName"))
    for k in range(r.count("nParts", codes.MAX_BODY_PARTS)):
        f = f"part[{k}]"
        part_id = r.i32(f + ".partID")
        if part_id == codes.EMPTY_PART_SLOT:
            continue
        part_type = r.i32(f + ".partType")
        if part_type == codes.PART_UNDEFINED:
            continue
        with _ids.decoding(part_id):
            try:
                part = _read_part(r, f, part_type)
            except (ArithmeticError, ValueError) as e:
                raise ProtocolError(f, f"cannot build the part from these values ({e})") from None
        _read_name_and_colors(r, f, part)
        body.add_part(part)
    return body


def _read_part(r: Reader, f: str, part_type: int) -> BodyPart:
    if part_type == codes.PART_ABSTRACT_SENSOR:
        raise ProtocolError(f + ".partType", "type 4 (abstract BODY_SENSOR) cannot be built")
    reader = _READERS.get(part_type)
    if reader is None:
        raise ProtocolError(f + ".partType", f"unknown body part type {part_type}")
    return reader(r, f)


def _outline(r: Reader, f: str) -> Tuple[Tuple[float, float], ...]:
    return r.points(f + ".outline", codes.MAX_OUTLINE_VERTICES)


def _read_target_sensor(r: Reader, f: str) -> BodyPart:
    outline = _outline(r, f)
    x, y, sight = r.f64(f + ".xDetector"), r.f64(f + ".yDetector"), r.f64(f + ".sightAngle")
    width, max_range = r.f64(f + ".width"), r.f64(f + ".maxRange")
    return TargetSensor(outline, x, y, sight, width, max_range, r.i32(f + ".nWidthBin"), r.i32(f + ".nRangeBin"))


def _read_range_sensor(r: Reader, f: str) -> BodyPart:
    outline = _outline(r, f)
    x, y, sight = r.f64(f + ".xDetector"), r.f64(f + ".yDetector"), r.f64(f + ".sightAngle")
    return RangeSensor(outline, x, y, sight, r.f64(f + ".maxRange"), r.i32(f + ".nRangeBin"))


def _read_paint_sensor(r: Reader, f: str) -> BodyPart:
    outline = _outline(r, f)
    x, y = r.f64(f + ".xDetector"), r.f64(f + ".yDetector")
    n = r.count(f + ".nRegions", codes.MAX_REGIONS)
    return PaintSensor(outline, x, y, [r.i32(f"{f}.region[{i}]") for i in range(n)])


def _read_wheel_system(r: Reader, f: str) -> BodyPart:
    """The Ackerman limit on the wire is the sender's central limit; like the Java simulator this
    passes it on as an inner-wheel limit, which derives a slightly smaller central one."""
    system: WheelSystem
    if r.i32(f + ".systemType") == _DIFFERENTIAL:
        system = DifferentialSteering(r.f64(f + ".trackWidth"), r.f64(f + ".driveWheelRadius"))
    else:
        track, base = r.f64(f + ".trackWidth"), r.f64(f + ".wheelBase")
        radius, steering = r.f64(f + ".driveWheelRadius"), r.f64(f + ".maxAbsSteeringAngle")
        system = AckermanSteering(track, base, radius, steering, r.boolean(f + ".dualSteering"))
    for k in range(r.count(f + ".nWheels", codes.MAX_WHEELS)):
        system.add_wheel(_read_wheel(r, f"{f}.wheel[{k}]"))
    return system


def _read_wheel(r: Reader, f: str) -> Wheel:
    wheel_type = r.i32(f + ".wheelType")
    outline = _outline(r, f)
    x, y = r.f64(f + ".x"), r.f64(f + ".y")
    radius = r.f64(f + ".wheelRadius")
    max_steering = r.f64(f + ".maxAbsSteeringAngle")
    intervals = r.i32(f + ".encoderIntervalCount")
    wheel = Caster(outline, x, y) if wheel_type == _CASTER else Wheel(outline, x, y, radius, max_steering)
    wheel.add_encoder(intervals)
    return wheel


_READERS: Dict[int, Callable[[Reader, str], BodyPart]] = {
    codes.PART_WHEEL_SYSTEM: _read_wheel_system,
    codes.PART_CIRCLE: lambda r, f: Circle(r.f64(f + ".xCenter"), r.f64(f + ".yCenter"), r.f64(f + ".radius")),
    codes.PART_SHAPE: lambda r, f: Shape(_outline(r, f)),
    codes.PART_TARGET_SENSOR: _read_target_sensor,
    codes.PART_CONTACT_SENSOR: lambda r, f: ContactSensor(_outline(r, f)),
    codes.PART_RANGE_SENSOR: _read_range_sensor,
    codes.PART_PAINT_SENSOR: _read_paint_sensor,
    codes.PART_PAINTER: lambda r, f: Painter(_outline(r, f)),
}


def _read_name_and_colors(r: Reader, f: str, part: BodyPart) -> None:
    """Wheels carry no name or colours: like RP1 0.60 they take the system's fill colour as both
    their fill and their line colour."""
    part.name = r.utf(f + ".name")
    fill = r.color(f + ".fillColor")
    part.fill_color = fill
    part.line_color = r.color(f + ".lineColor")
    part.hot_fill_color = r.color(f + ".hotFillColor")
    part.hot_line_color = r.color(f + ".hotLineColor")
    for wheel in getattr(part, "wheels", ()):
        wheel.fill_color = wheel.line_color = fill
