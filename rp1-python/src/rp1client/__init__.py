"""rp1client: robot brains in Python for the RP1 (Rossum's Playhouse) simulator.

A second, independent implementation of the RP1 wire protocol (docs/protocol.md in the RP1
repository), with the model of the Java client library in Python's idiom: a :class:`Client` that
connects, sends the robot's :class:`Body`, registers handlers per event type (and per sensor), sends
requests, and runs the event loop, acknowledging interlocked events for you.
"""

from .body import (Body, BodyPart, Circle, ContactSensor, PaintSensor, Painter, RangeSensor, Sensor, Shape,
                   TargetSensor, next_part_id, set_next_part_id)
from .bodycodec import decode_body, encode_body
from .client import Client
from .errors import ProtocolError, SettingsError
from .events import (ContactSensorEvent, EncoderStatusEvent, Event, HeartbeatEvent, MotionHaltedEvent,
                     MotionStartedEvent, MouseClickEvent, PaintSensorEvent, PlacementEvent, PlanEvent, PositionEvent,
                     RangeSensorEvent, SensorEvent, TargetSelectionEvent, TargetSensorEvent, TimeoutEvent, decode_event,
                     encode_event)
from .plan import NavLink, NavNode, Paint, Placement, Plan, PlanObject, Target, Wall, decode_plan, encode_plan
from .requests import (ActuatorControlRequest, EncoderStatusRequest, HaltRequest, HeartbeatRequest, MotionRequest,
                       PainterChangeRequest, PlacementRequest, PlanRequest, PositionRequest, Request,
                       SensorStatusRequest, SetPositionRequest, SubscriptionRequest, TargetSelectionRequest,
                       TimeoutRequest, decode_request, encode_request)
from .run import report_run_result, run_parameter, run_seed
from .settings import ClientSettings
from .steering import AckermanSteering, Caster, DifferentialSteering, Wheel, WheelSystem
from .wire import Color

__all__ = [
    "AckermanSteering", "ActuatorControlRequest", "Body", "BodyPart", "Caster", "Circle", "Client",
    "ClientSettings", "Color", "ContactSensor", "ContactSensorEvent", "DifferentialSteering",
    "EncoderStatusEvent", "EncoderStatusRequest", "Event", "HaltRequest", "HeartbeatEvent", "HeartbeatRequest",
    "MotionHaltedEvent", "MotionRequest", "MotionStartedEvent", "MouseClickEvent", "NavLink", "NavNode", "Paint",
    "PaintSensor", "PaintSensorEvent", "Painter", "PainterChangeRequest", "Placement", "PlacementEvent",
    "PlacementRequest", "Plan", "PlanEvent", "PlanObject", "PlanRequest", "PositionEvent", "PositionRequest",
    "ProtocolError", "RangeSensor", "RangeSensorEvent", "Request", "SensorEvent", "Sensor", "SensorStatusRequest",
    "SetPositionRequest", "SettingsError", "Shape", "SubscriptionRequest", "Target", "TargetSelectionEvent",
    "TargetSelectionRequest", "TargetSensor", "TargetSensorEvent", "TimeoutEvent", "TimeoutRequest", "Wall",
    "Wheel", "WheelSystem", "decode_body", "decode_event", "decode_plan", "decode_request", "encode_body",
    "encode_event", "encode_plan", "encode_request", "next_part_id", "report_run_result", "run_parameter", "run_seed",
    "set_next_part_id",
]
