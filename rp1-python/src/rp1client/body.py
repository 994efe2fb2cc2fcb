"""A robot's body: its parts, as the client describes them to the simulator (docs/protocol.md section 8).

Coordinates are body coordinates: metres, x forward, y to the left, origin at the robot's reference
point (usually the centre of the drive axle). Every part takes an id when it is constructed, from one
counter per process that starts at 1 (section 8.6): requests and events name sensors, painters, the
wheel system and encoders by these ids, and the simulator numbers the wheels of a wheel system after
the system's own id, so build wheels right after their wheel system.
"""

import threading
from contextlib import contextmanager
from typing import ClassVar, Iterator, List, Optional, Sequence, Tuple, Type, TypeVar, Union

from . import codes
from .wire import Color

Point = Tuple[float, float]

#: Edges shorter than 1 mm (squared length below this) are dropped from outlines.
_MIN_EDGE_SQUARED = 1.0e-6


class _PartIds:
    """The process-wide part-id counter, with a per-thread override used while decoding a body."""

    def __init__(self) -> None:
        self._next = 1
        self._lock = threading.Lock()
        self._decoding = threading.local()

    def take(self) -> int:
        override = getattr(self._decoding, "next", None)
        if override is not None:
            self._decoding.next = override + 1
            return int(override)
        with self._lock:
            n = self._next
            self._next += 1
            return n

    def peek(self) -> int:
        with self._lock:
            return self._next

    def set_next(self, n: int) -> None:
        with self._lock:
            self._next = n

    @contextmanager
    def decoding(self, first_id: int) -> Iterator[None]:
        """Parts built on this thread inside the block get ``first_id``, ``first_id + 1``, ..."""
        self._decoding.next = first_id
        try:
            yield
        finally:
            self._decoding.next = None


_ids = _PartIds()


def next_part_id() -> int:
    """The id the next part constructed in this process will get."""
    return _ids.peek()


def set_next_part_id(n: int) -> None:
    """Sets the id the next constructed part will get (as the Java library's
    ``setNextPartSerialNumber``); for tests that need known ids."""
    _ids.set_next(n)


def outline_vertices(points: Sequence[Point]) -> Tuple[Point, ...]:
    """The closed outline through ``points``, as the start point of each of its edges.

    An edge is made from each kept point to the next point at least 1 mm away, then a closing edge
    back to the first point unless the last kept point lies within 1 mm of it. This is what a body
    specification transmits, and what the simulator rebuilds the same outline from.
    """
    pts = [(float(x), float(y)) for x, y in points]
    if not pts:
        return ()
    first_x, first_y = pts[0]
    px, py = first_x, first_y
    vertices: List[Point] = []
    for x, y in pts[1:]:
        dx, dy = x - px, y - py
        if dx * dx + dy * dy < _MIN_EDGE_SQUARED:
            continue
        vertices.append((px, py))
        px, py = x, y
    dx, dy = first_x - px, first_y - py
    if dx * dx + dy * dy >= _MIN_EDGE_SQUARED:
        vertices.append((px, py))
    return tuple(vertices)


def rectangle_points(x: float, y: float, length: float, width: float) -> List[Point]:
    """An axis-aligned rectangle centred on (x, y), counter-clockwise from its rear right corner."""
    hx = length / 2.0
    hy = width / 2.0
    return [(x - hx, y - hy), (x + hx, y - hy), (x + hx, y + hy), (x - hx, y + hy)]


class BodyPart:
    """A part of a robot body: a name, four colours, and an id taken at construction.

    The colours are the fill and line colours, and the "hot" ones used while a sensor detects
    something or a painter paints; None means "not drawn".
    """

    wire_type: ClassVar[int] = codes.PART_UNDEFINED
    default_name: ClassVar[str] = "Unnamed"

    def __init__(self) -> None:
        self._id = _ids.take()
        self.name: Optional[str] = self.default_name
        self.fill_color: Optional[Color] = Color.LIGHT_GRAY
        self.line_color: Optional[Color] = Color.LIGHT_GRAY
        self.hot_fill_color: Optional[Color] = Color.ORANGE
        self.hot_line_color: Optional[Color] = Color.ORANGE

    @property
    def id(self) -> int:
        """The part id: how requests and events refer to this part."""
        return self._id

    def set_color(self, color: Optional[Color]) -> None:
        """Sets both the fill and the line colour."""
        self.fill_color = color
        self.line_color = color

    def __repr__(self) -> str:
        return f"{type(self).__name__}(id={self._id}, name={self.name!r})"


class Shape(BodyPart):
    """A part with a polygonal outline (chassis, housing, bumper): it is drawn and it collides.

    ``points`` are the outline's vertices; the outline closes itself and drops edges shorter than
    1 mm (see :func:`outline_vertices`).
    """

    wire_type = codes.PART_SHAPE

    def __init__(self, points: Sequence[Point] = ()) -> None:
        super().__init__()
        self.outline: Tuple[Point, ...] = outline_vertices(points)


class Circle(BodyPart):
    """A circular part, e.g. a round chassis, sent by centre and radius."""

    wire_type = codes.PART_CIRCLE
    default_name = "Unnamed Circle"

    def __init__(self, x: float, y: float, radius: float) -> None:
        super().__init__()
        self.x = x
        self.y = y
        self.radius = radius


class Sensor(Shape):
    """A shape that senses something; its default hot line colour is red."""

    def __init__(self, points: Sequence[Point] = ()) -> None:
        super().__init__(points)
        self.hot_line_color = Color.RED


class ContactSensor(Sensor):
    """A bumper: reports touching a wall at the end of a motion, and the release when the next starts."""

    wire_type = codes.PART_CONTACT_SENSOR
    default_name = "Unnamed Contact Sensor"


class RangeSensor(Sensor):
    """A ray from the detector point along the heading plus ``sight_angle`` (radians), up to
    ``max_range`` metres (at most 1e6), reporting the distance to the first wall; the range is
    split into ``n_range_bin`` bins (at least 1) and moving within a bin is not reported."""

    wire_type = codes.PART_RANGE_SENSOR
    default_name = "Unnamed Range Sensor"

    def __init__(self, points: Sequence[Point], x_detector: float, y_detector: float, sight_angle: float,
                 max_range: float, n_range_bin: int) -> None:
        super().__init__(points)
        self.x_detector = x_detector
        self.y_detector = y_detector
        self.sight_angle = sight_angle
        self.max_range = min(max_range, 1.0e6)
        self.n_range_bin = max(1, n_range_bin)


class TargetSensor(Sensor):
    """Sees targets like a flashlight beam: detector point, sight axis, field of view ``width``
    (radians, 0 = all directions), ``max_range`` metres, and bins across width and range."""

    wire_type = codes.PART_TARGET_SENSOR
    default_name = "Unnamed Target Sensor"

    def __init__(self, points: Sequence[Point], x_detector: float, y_detector: float, sight_angle: float,
                 width: float, max_range: float, n_width_bin: int, n_range_bin: int) -> None:
        super().__init__(points)
        self.x_detector = x_detector
        self.y_detector = y_detector
        self.sight_angle = sight_angle
        self.width = width
        self.max_range = max_range
        self.n_width_bin = n_width_bin
        self.n_range_bin = n_range_bin


class PaintSensor(Sensor):
    """Senses floor paint at one detector point; sensitive to the listed region codes, or to all
    regions when there is no list."""

    wire_type = codes.PART_PAINT_SENSOR
    default_name = "Unnamed Paint Sensor"

    def __init__(self, points: Sequence[Point], x_detector: float, y_detector: float,
                 region_sensitivity: Optional[Sequence[int]] = None) -> None:
        super().__init__(points)
        self.x_detector = x_detector
        self.y_detector = y_detector
        self.region_sensitivity = region_sensitivity

    @property
    def region_sensitivity(self) -> Optional[Tuple[int, ...]]:
        """The region codes sensed, or None for every region."""
        return self._regions

    @region_sensitivity.setter
    def region_sensitivity(self, regions: Optional[Sequence[int]]) -> None:
        self._regions = tuple(regions) if regions else None


class Painter(Shape):
    """Leaves a paint trail while active, at the trailer point with the trailer width and the first
    paint colour. Only the outline is in the body specification; the trailer and colours travel in
    the painter activation request, which needs both a colour and a trailer."""

    wire_type = codes.PART_PAINTER

    def __init__(self, points: Sequence[Point] = ()) -> None:
        super().__init__(points)
        self.trailer_defined = False
        self.trailer_x = 0.0
        self.trailer_y = 0.0
        self.trailer_width = 0.0
        self.paint_colors: Optional[Tuple[Color, ...]] = None
        self.active = False

    def set_trailer_position(self, x: float, y: float) -> None:
        """Where the trail is laid, body coordinates; the trailer becomes defined."""
        self.trailer_x = x
        self.trailer_y = y
        self.trailer_defined = True

    def set_trailer_width(self, width: float) -> None:
        """Width of the trail, metres (negative values become 0); the trailer becomes defined."""
        self.trailer_width = max(0.0, width)
        self.trailer_defined = True

    def remove_trailer(self) -> None:
        """Forgets the trailer: position and width 0, no longer defined."""
        self.trailer_defined = False
        self.trailer_x = self.trailer_y = self.trailer_width = 0.0

    def set_paint_color(self, colors: Union[None, Color, Sequence[Color]]) -> None:
        """One colour or a list of them (the trail is drawn in the first); None for no colour."""
        if colors is None:
            self.paint_colors = None
        elif isinstance(colors, Color):
            self.paint_colors = (colors,)
        else:
            self.paint_colors = tuple(colors) or None


P = TypeVar("P", bound=BodyPart)


class Body:
    """A robot body: its parts in the order they were added, which is also the drawing order."""

    def __init__(self, name: Optional[str]) -> None:
        self.name = name
        self.parts: List[BodyPart] = []
        self.wheel_system: Optional[BodyPart] = None

    def add_part(self, part: BodyPart) -> BodyPart:
        """Adds a part and returns it; a wheel system becomes the body's ``wheel_system``."""
        if not isinstance(part, BodyPart):
            raise TypeError(f"add_part expects a BodyPart, got {part!r}")
        self.parts.append(part)
        if part.wire_type == codes.PART_WHEEL_SYSTEM:
            self.wheel_system = part
        return part

    def all_parts(self) -> Iterator[BodyPart]:
        """Every part, each wheel system followed by its wheels."""
        for part in self.parts:
            yield part
            yield from getattr(part, "wheels", ())

    def part_by_name(self, name: str) -> Optional[BodyPart]:
        """The first part (wheels included) with exactly this name, or None."""
        return next((p for p in self.all_parts() if p.name == name), None)

    def part_by_id(self, part_id: int) -> Optional[BodyPart]:
        """The part (wheels included) with this id, or None."""
        return next((p for p in self.all_parts() if p.id == part_id), None)

    def parts_of(self, kind: Type[P]) -> List[P]:
        """The parts of one class, in part order."""
        return [p for p in self.parts if isinstance(p, kind)]

    @property
    def sensors(self) -> List[Sensor]:
        return self.parts_of(Sensor)

    @property
    def painters(self) -> List[Painter]:
        return self.parts_of(Painter)

    def __repr__(self) -> str:
        return f"Body({self.name!r}, {len(self.parts)} parts)"
