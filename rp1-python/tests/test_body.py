"""Body parts: ids, outlines and defaults as the Java library makes them, and the motion helpers."""

import math

import pytest

import rp1client as rp
from rp1client.wire import Writer


def test_part_ids_follow_construction_order_across_bodies() -> None:
    rp.set_next_part_id(1)
    first = rp.Body("one").add_part(rp.Circle(0, 0, 0.1))
    steering = rp.DifferentialSteering(0.3, 0.05)
    steering.add_default_wheels(0.05, 0.02)
    sonar = rp.RangeSensor([(0, 0), (0.1, 0), (0, 0.1)], 0.1, 0, 0, 1, 4)
    rp.Body("two").add_part(steering)
    assert [first.id, steering.id, steering.left_wheel.id, steering.right_wheel.id, sonar.id] == [1, 2, 3, 4, 5]
    assert rp.next_part_id() == 6


def test_received_wheels_get_the_ids_after_their_wheel_system() -> None:
    steering = rp.AckermanSteering(0.3, 0.4, 0.05, math.radians(30), dual_steering=True)
    steering.add_default_wheels(0.05, 0.02, 0.05, 0.01)
    body = rp.Body("car")
    body.add_part(steering)
    received = rp.decode_body(rp.encode_body(body))
    system = received.wheel_system
    assert system.id == steering.id
    assert [w.id for w in system.wheels] == [steering.id + k for k in range(1, 5)]
    assert [w.id for w in steering.wheels] == [w.id for w in system.wheels], "built right after the system"
    assert [w.is_steerable for w in system.wheels] == [True] * 4


def test_an_outline_drops_edges_shorter_than_a_millimetre_and_closes_itself() -> None:
    shape = rp.Shape([(0, 0), (1, 0), (1, 0.0005), (1, 1), (0, 1), (0.0002, 0)])
    assert shape.outline == ((0, 0), (1, 0), (1, 1), (0, 1))


def test_default_names_and_colours_are_the_java_librarys() -> None:
    sensor = rp.ContactSensor([(0, 0), (1, 0), (0, 1)])
    assert (sensor.name, sensor.fill_color, sensor.hot_fill_color, sensor.hot_line_color) == (
        "Unnamed Contact Sensor", rp.Color.LIGHT_GRAY, rp.Color.ORANGE, rp.Color.RED)
    assert rp.Shape().hot_line_color == rp.Color.ORANGE
    assert rp.DifferentialSteering(0.2, 0.05).name == "Differential Steering"


def test_wheel_system_colours_reach_its_wheels() -> None:
    steering = rp.DifferentialSteering(0.2, 0.05)
    steering.add_default_wheels(0.05, 0.02)
    steering.set_color(rp.Color.DARK_GRAY)
    assert {w.fill_color for w in steering.wheels} == {rp.Color.DARK_GRAY}
    assert {w.line_color for w in steering.wheels} == {rp.Color.DARK_GRAY}


def test_range_sensor_limits_are_applied_when_built() -> None:
    sonar = rp.RangeSensor([(0, 0), (1, 0), (0, 1)], 0, 0, 0, 5e6, 0)
    assert (sonar.max_range, sonar.n_range_bin) == (1e6, 1)


def test_a_body_with_nothing_to_send_is_refused() -> None:
    with pytest.raises(ValueError, match="no part"):
        rp.encode_body(rp.Body("empty"))


def test_every_kind_of_part_survives_a_round_trip() -> None:
    body = rp.Body("all")
    body.add_part(rp.Shape([(0, 0), (0.2, 0), (0.2, 0.2)]))
    body.add_part(rp.TargetSensor([(0, 0), (0.1, 0), (0, 0.1)], 0.1, 0, 0.2, 1.0, 2.0, 3, 4))
    body.add_part(rp.PaintSensor([(0, 0), (0.1, 0), (0, 0.1)], 0.05, 0.0, [3, 5]))
    body.add_part(rp.Painter([(0, 0), (0.1, 0), (0, 0.1)]))
    steering = body.add_part(rp.DifferentialSteering(0.2, 0.05))
    steering.add_default_caster_wheel(-0.1, 0.0, 0.02, 0.01)
    payload = rp.encode_body(body)
    received = rp.decode_body(payload)
    assert rp.encode_body(received) == payload
    assert [type(p).__name__ for p in received.parts] == [
        "Shape", "TargetSensor", "PaintSensor", "Painter", "DifferentialSteering"]
    assert received.parts[2].region_sensitivity == (3, 5)
    assert isinstance(received.wheel_system.wheels[0], rp.Caster)


def test_an_ackerman_body_the_simulator_cannot_build_is_a_protocol_error() -> None:
    w = Writer().utf("car").i32(1).i32(1).i32(1).i32(1)
    for value in (0.3, 0.4, 0.05, 0.0):
        w.f64(value)
    w.boolean(False).i32(0)
    with pytest.raises(rp.ProtocolError, match=r"^part\[0\]: cannot build the part"):
        rp.decode_body(w.getvalue())


def test_ackerman_steering_limits_follow_from_the_inner_wheel_limit() -> None:
    car = rp.AckermanSteering(0.3, 0.4, 0.05, math.radians(30))
    assert car.min_turn_radius == pytest.approx(0.4 / math.tan(math.radians(30)) + 0.15)
    assert car.max_abs_steering_angle == pytest.approx(math.atan(0.4 / car.min_turn_radius))
    assert rp.AckermanSteering(0.3, 0.4, 0.05, math.radians(89)).inner_max_angle == pytest.approx(math.radians(85))
    assert car.get_motion_request_for_pivot(1, 1, 1) is None
    request = car.get_motion_request_using_velocity_and_steering_angle(0.5, 1.0, 2.0)
    assert request.rotational_velocity == pytest.approx(0.5 * math.tan(car.max_abs_steering_angle) / 0.4)


@pytest.mark.parametrize("goal, expected", [
    ((1.0, 0.0), rp.MotionRequest(0.5, 0.0, 2.0)),
    ((-1.0, 0.0), rp.MotionRequest(-0.5, 0.0, 2.0)),
    ((1.0, 1.0), rp.MotionRequest(0.5, 0.5, math.pi)),
    ((1.0, -1.0), rp.MotionRequest(0.5, -0.5, math.pi)),
])
def test_motion_towards_a_goal_is_a_line_or_the_arc_through_it(goal, expected: rp.MotionRequest) -> None:
    request = rp.DifferentialSteering(0.2, 0.05).get_motion_request(*goal, 0.5)
    assert request.linear_velocity == expected.linear_velocity
    assert request.rotational_velocity == pytest.approx(expected.rotational_velocity)
    assert request.duration == pytest.approx(expected.duration)


def test_a_pivot_turns_at_a_quarter_turn_per_second_towards_the_goal() -> None:
    steering = rp.DifferentialSteering(0.2, 0.05)
    assert steering.get_motion_request_for_pivot(0.0, -1.0, 9.9) == rp.MotionRequest(0.0, -math.pi / 2, 1.0)
    assert steering.get_motion_request_for_pivot(1.0, 0.0, 0.5) is None
    assert steering.get_motion_request(0.0001, 0.0, 0.5) is None


def test_differential_wheel_speeds_give_linear_and_turn_rates() -> None:
    steering = rp.DifferentialSteering(0.2, 0.05)
    request = steering.get_motion_request_using_wheel_rotational_velocities(2.0, 6.0, 3.0)
    assert (request.linear_velocity, request.rotational_velocity, request.duration) == pytest.approx((0.2, 1.0, 3.0))
