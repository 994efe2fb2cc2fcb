"""Wheel systems and wheels, and the arithmetic from goals or wheel speeds to motion requests.

The drive axle is centred on the body origin along the body's y axis. A wheel system's part id
names it in actuator-control requests; its wheels get the following ids when they are built right
after it (``add_default_wheels`` does), which is what the simulator assumes.
"""

import math
from typing import ClassVar, List, Optional, Sequence, Tuple

from . import codes
from .body import BodyPart, Point, Shape, rectangle_points
from .requests import ActuatorControlRequest, MotionRequest
from .wire import Color

#: Durations, speeds and turn rates below this make a null motion.
_NULL_LIMIT = 1.0e-4
#: A goal farther than this turn radius (metres) is approached in a straight line.
_MAX_ARC_RADIUS = 1000.0
#: Pivots always turn at 90 degrees per second.
_PIVOT_RATE = math.pi / 2.0
#: Steering angles at most this large (radians) drive straight.
_STRAIGHT_ANGLE = 1.0e-5
#: Ackerman inner-wheel steering limits are capped at 85 degrees.
_MAX_INNER_ANGLE = math.radians(85.0)


class Wheel(Shape):
    """A wheel: drawn, never colliding, optionally with an encoder whose id is the wheel's id.

    ``x``, ``y`` is the hub in body coordinates; ``max_abs_steering_angle`` 0 means a fixed wheel.
    """

    is_caster: ClassVar[bool] = False

    def __init__(self, points: Sequence[Point], x: float, y: float, radius: float,
                 max_abs_steering_angle: float = 0.0) -> None:
        super().__init__(points)
        self.x = x
        self.y = y
        self.radius = radius
        self.max_abs_steering_angle = max_abs_steering_angle
        self.encoder_interval_count = 0

    @property
    def is_steerable(self) -> bool:
        return self.max_abs_steering_angle > 0.0

    def add_encoder(self, n_intervals: int) -> "Optional[Wheel]":
        """Fits an encoder with ``n_intervals`` per revolution; returns the wheel (which is the
        encoder to pass to ``send_encoder_status_request``), or None if ``n_intervals`` < 1."""
        if n_intervals <= 0:
            return None
        self.encoder_interval_count = n_intervals
        return self


class Caster(Wheel):
    """A free-swivelling caster with its pivot at (x, y): radius 0, a full turn of steering, no encoder."""

    is_caster = True

    def __init__(self, points: Sequence[Point], x: float, y: float) -> None:
        super().__init__(points, x, y, 0.0, 2.0 * math.pi)

    @property
    def is_steerable(self) -> bool:
        return True


class WheelSystem(BodyPart):
    """The robot's locomotion: geometry, wheels, and motion-request helpers."""

    wire_type = codes.PART_WHEEL_SYSTEM
    default_name = "Wheel System"

    def __init__(self, track_width: float, drive_wheel_radius: float, wheel_base: float = 0.0) -> None:
        self.wheels: List[Wheel] = []
        super().__init__()
        self.track_width = track_width
        self.drive_wheel_radius = drive_wheel_radius
        self.wheel_base = wheel_base

    @property  # type: ignore[override]
    def fill_color(self) -> Optional[Color]:
        """Setting it also sets the fill colour of every wheel added so far."""
        return self._fill_color

    @fill_color.setter
    def fill_color(self, color: Optional[Color]) -> None:
        self._fill_color = color
        for w in self.wheels:
            w.fill_color = color

    @property  # type: ignore[override]
    def line_color(self) -> Optional[Color]:
        """Setting it also sets the line colour of every wheel added so far."""
        return self._line_color

    @line_color.setter
    def line_color(self, color: Optional[Color]) -> None:
        self._line_color = color
        for w in self.wheels:
            w.line_color = color

    def add_wheel(self, wheel: Wheel) -> Wheel:
        """Adds a wheel (for drawing and encoders) and returns it."""
        if not isinstance(wheel, Wheel):
            raise TypeError(f"add_wheel expects a Wheel, got {wheel!r}")
        self.wheels.append(wheel)
        return wheel

    def _add_axle_wheels(self, x: float, radius: float, width: float, left_name: str,
                         right_name: str) -> Tuple[Wheel, Wheel]:
        y = self.track_width / 2.0
        length = 2 * radius
        left = Wheel(rectangle_points(x, y, length, width), x, y, radius)
        right = Wheel(rectangle_points(x, -y, length, width), x, -y, radius)
        left.name = left_name
        right.name = right_name
        self.add_wheel(left)
        self.add_wheel(right)
        return left, right

    def add_default_wheels(self, wheel_radius: float, wheel_width: float) -> None:
        """Adds fixed wheels on the axle at y = +track_width/2 ("left wheel", built first) and
        -track_width/2 ("right wheel"), each drawn as a 2 radius by width rectangle."""
        self._add_axle_wheels(0.0, wheel_radius, wheel_width, "left wheel", "right wheel")

    def add_default_caster_wheel(self, x: float, y: float, wheel_radius: float, wheel_width: float) -> Caster:
        """Adds a caster pivoting at (x, y), drawn as a 2 radius by width rectangle."""
        caster = Caster(rectangle_points(x, y, 2 * wheel_radius, wheel_width), x, y)
        caster.name = "caster wheel"
        self.add_wheel(caster)
        return caster

    def wheel_for_id(self, part_id: int) -> Optional[Wheel]:
        """The wheel with this part (encoder) id, or None."""
        return next((w for w in self.wheels if w.id == part_id), None)

    def get_motion_request(self, x: float, y: float, speed: float) -> Optional[MotionRequest]:
        """A request that takes the robot to (x, y) in robot coordinates at ``speed`` m/s: straight,
        or along the arc tangent to the heading through the goal (backing if it is behind). None if
        the goal is too close or the speed too small."""
        return motion_towards(x, y, speed)

    def get_motion_request_for_pivot(self, x: float, y: float, speed: float) -> Optional[MotionRequest]:
        """A turn in place to face (x, y) (robot coordinates) at pi/2 rad/s; the speed is ignored,
        as in RP1 0.60. None if the turn would take under 1 ms."""
        return pivot_towards(x, y)


class DifferentialSteering(WheelSystem):
    """Two independently driven wheels on one axle ``track_width`` apart (wheelchair style)."""

    default_name = "Differential Steering"

    def __init__(self, track_width: float, drive_wheel_radius: float) -> None:
        super().__init__(track_width, drive_wheel_radius)
        self.left_wheel: Optional[Wheel] = None
        self.right_wheel: Optional[Wheel] = None

    def add_default_wheels(self, wheel_radius: float, wheel_width: float) -> None:
        self.left_wheel, self.right_wheel = self._add_axle_wheels(
            0.0, wheel_radius, wheel_width, "left wheel", "right wheel")

    def add_encoders_to_default_wheels(self, n_intervals: int) -> Optional[Tuple[Optional[Wheel], Optional[Wheel]]]:
        """Fits both default wheels with encoders; (left, right), or None without default wheels."""
        if self.left_wheel is None or self.right_wheel is None:
            return None
        return self.left_wheel.add_encoder(n_intervals), self.right_wheel.add_encoder(n_intervals)

    def get_motion_request_using_wheel_velocities(self, v_left: float, v_right: float,
                                                  duration: float) -> MotionRequest:
        """From the wheels' linear velocities (m/s): v = (l + r)/2, omega = (r - l)/track width."""
        return MotionRequest((v_left + v_right) / 2.0, (v_right - v_left) / self.track_width, duration)

    def get_motion_request_using_wheel_rotational_velocities(self, rot_left: float, rot_right: float,
                                                             duration: float) -> MotionRequest:
        """From the wheels' rotational velocities (rad/s)."""
        r = self.drive_wheel_radius
        return self.get_motion_request_using_wheel_velocities(rot_left * r, rot_right * r, duration)

    def get_control_request_for_wheel_rotation(self, left: float, right: float) -> ActuatorControlRequest:
        """Turns the wheels at these rotational velocities (rad/s) until further notice; both 0 give
        a parameterless HALT, which ``send_actuator_control_request`` sends as a halt request."""
        if left == 0.0 and right == 0.0:
            return ActuatorControlRequest(self.id, ActuatorControlRequest.HALT)
        request = ActuatorControlRequest(self.id, ActuatorControlRequest.ACTIVATE)
        request.add_parameter("leftRotationalVelocity", left)
        request.add_parameter("rightRotationalVelocity", right)
        return request


class AckermanSteering(WheelSystem):
    """Automobile steering: driven wheels and steerable front (or, with ``dual_steering``, front and
    rear) wheels. The inner-wheel limit (capped at 85 degrees) gives the minimum turn radius and the
    central steering limit ``max_abs_steering_angle``. Such a robot cannot pivot."""

    default_name = "Ackerman Steering"

    def __init__(self, track_width: float, wheel_base: float, drive_wheel_radius: float,
                 max_abs_inner_wheel_steering_angle: float, dual_steering: bool = False) -> None:
        super().__init__(track_width, drive_wheel_radius, wheel_base)
        self.dual_steering = dual_steering
        self.inner_max_angle = min(max_abs_inner_wheel_steering_angle, _MAX_INNER_ANGLE)
        self.min_turn_radius = self._steering_base() / math.tan(self.inner_max_angle) + track_width / 2.0
        self.max_abs_steering_angle = math.atan(self._steering_base() / self.min_turn_radius)

    def _steering_base(self) -> float:
        return self.wheel_base / 2.0 if self.dual_steering else self.wheel_base

    def add_default_wheels(self, wheel_radius: float, wheel_width: float, stub_length: float = 0.0,
                           stub_width: float = 0.0) -> None:
        """Adds four wheels in this order: left and right rear, left and right front. Without dual
        steering the rear axle is at x = 0 and the front one at x = wheel base; with it the axles are
        at -/+ wheel base/2 and all four wheels steer. A steering wheel is drawn with a stub axle of
        ``stub_length`` by ``stub_width`` towards the centre line."""
        rear_x = -self.wheel_base / 2.0 if self.dual_steering else 0.0
        front_x = self.wheel_base / 2.0 if self.dual_steering else self.wheel_base
        if self.dual_steering:
            self._add_steering_wheel("left rear wheel", rear_x, 1, wheel_radius, wheel_width, stub_length, stub_width)
            self._add_steering_wheel("right rear wheel", rear_x, -1, wheel_radius, wheel_width, stub_length, stub_width)
        else:
            self._add_axle_wheels(rear_x, wheel_radius, wheel_width, "left rear wheel", "right rear wheel")
        self._add_steering_wheel("left front wheel", front_x, 1, wheel_radius, wheel_width, stub_length, stub_width)
        self._add_steering_wheel("right front wheel", front_x, -1, wheel_radius, wheel_width, stub_length, stub_width)

    def _add_steering_wheel(self, name: str, x: float, side: int, radius: float, width: float,
                            stub_length: float, stub_width: float) -> None:
        y = side * self.track_width / 2.0
        local = [(-radius, width / 2), (-radius, -width / 2), (-stub_width / 2, -width / 2),
                 (-stub_width / 2, -stub_length), (stub_width / 2, -stub_length), (stub_width / 2, -width / 2),
                 (radius, -width / 2), (radius, width / 2)]
        wheel = Wheel([(px + x, y + side * py) for px, py in local], x, y, radius, self.inner_max_angle)
        wheel.name = name
        self.add_wheel(wheel)

    def _clamp(self, angle: float) -> float:
        return max(-self.max_abs_steering_angle, min(angle, self.max_abs_steering_angle))

    def get_turn_radius_for_steering_angle(self, angle: float) -> float:
        """base / tan(angle) for the limited angle; negative for right turns, infinite for 0."""
        clamped = self._clamp(angle)
        return math.inf if clamped == 0.0 else self._steering_base() / math.tan(clamped)

    def get_motion_request_using_velocity_and_steering_angle(self, velocity: float, steering_angle: float,
                                                             duration: float) -> MotionRequest:
        """Drive at ``velocity`` m/s with the central steering angle (limited) for ``duration`` s."""
        w = 0.0 if abs(steering_angle) <= _STRAIGHT_ANGLE else velocity / self.get_turn_radius_for_steering_angle(
            steering_angle)
        return MotionRequest(velocity, w, duration)

    def get_motion_request_using_wheel_rotational_velocity_and_steering_angle(
            self, wheel_rotational_velocity: float, steering_angle: float, duration: float) -> MotionRequest:
        """As above, the velocity given as drive-wheel rad/s."""
        return self.get_motion_request_using_velocity_and_steering_angle(
            wheel_rotational_velocity * self.drive_wheel_radius, steering_angle, duration)

    def get_control_request_for_wheel_rotation_and_steering_angle(
            self, drive_rotational_velocity: float, steering_angle: float) -> ActuatorControlRequest:
        """ACTIVATE with "driveRotationalVelocity" (rad/s) and "steeringAngle" (radians), in that order."""
        request = ActuatorControlRequest(self.id, ActuatorControlRequest.ACTIVATE)
        request.add_parameter("driveRotationalVelocity", drive_rotational_velocity)
        request.add_parameter("steeringAngle", steering_angle)
        return request

    def map_velocity_to_wheel_rotational_velocity(self, velocity: float) -> float:
        return velocity / self.drive_wheel_radius

    def map_velocity_to_wheel_rpm(self, velocity: float) -> float:
        return 60.0 * velocity / (2.0 * math.pi * self.drive_wheel_radius)

    def map_wheel_rpm_to_velocity(self, rpm: float) -> float:
        return rpm * 2.0 * math.pi * self.drive_wheel_radius / 60.0

    def get_motion_request(self, x: float, y: float, speed: float) -> Optional[MotionRequest]:
        """Always None: goal seeking is not implemented for Ackerman steering."""
        return None

    def get_motion_request_for_pivot(self, x: float, y: float, speed: float) -> Optional[MotionRequest]:
        """Always None: an Ackerman robot cannot pivot."""
        return None


def motion_towards(x: float, y: float, speed: float) -> Optional[MotionRequest]:
    """The request a wheel system's ``get_motion_request`` returns (see there)."""
    s = abs(speed)
    if s < 1.0e-6:
        return None
    if y == 0.0:
        return _straight(x, s)
    s2 = x * x + y * y
    if s2 < 0.001:
        return None
    radius = s2 / (2.0 * abs(y))
    if radius > _MAX_ARC_RADIUS:
        return _straight(x, s)
    alpha = math.pi - 2.0 * math.atan2(abs(x), abs(y))
    distance = alpha * radius
    duration = distance / s
    if _too_short(duration) or distance < _NULL_LIMIT:
        return None
    w = (alpha if y > 0 else -alpha) / duration
    return MotionRequest(-s if x < 0 else s, w, duration)


def _straight(x: float, speed: float) -> Optional[MotionRequest]:
    distance = abs(x)
    duration = distance / speed
    if _too_short(duration) or distance < _NULL_LIMIT:
        return None
    return MotionRequest(-speed if x < 0 else speed, 0.0, duration)


def pivot_towards(x: float, y: float) -> Optional[MotionRequest]:
    """The request a wheel system's ``get_motion_request_for_pivot`` returns (see there)."""
    beta = math.atan2(y, x)
    w = _PIVOT_RATE if beta >= 0 else -_PIVOT_RATE
    duration = beta / w
    return None if _too_short(duration) else MotionRequest(0.0, w, duration)


def _too_short(duration: float) -> bool:
    return math.floor(1000.0 * duration) < 1.0
