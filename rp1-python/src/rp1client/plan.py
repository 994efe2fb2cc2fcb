"""The floor plan a client receives in a plan event, and its encoding (docs/protocol.md section 9).

Walls and obstacles arrive as polygon vertices, targets and placements as their geometry, paint as
its closed vertex list and fill colour, navigation nodes as a point, label and colour, and links by
the names of their nodes. What the wire does not carry (units, region codes, most colours and
labels) has the defaults the Java library gives a received plan.
"""

import math
from typing import ClassVar, Dict, Generic, Iterator, List, Optional, Sequence, Tuple, Type, TypeVar

from . import codes
from .errors import ProtocolError
from .wire import Color, Reader, Writer, read_exactly

Point = Tuple[float, float]


class PlanObject:
    """An object of the floor plan; names are unique within a plan."""

    type_code: ClassVar[int] = 0
    kind: ClassVar[str] = "object"

    def __init__(self, name: str) -> None:
        self.name = name
        self.label: Optional[str] = None
        self.selected = True
        self.fill_color: Optional[Color] = Color.LIGHT_GRAY
        self.line_color: Optional[Color] = Color.LIGHT_GRAY

    def __repr__(self) -> str:
        return f"{type(self).__name__}({self.name!r})"

    def _write(self, w: Writer) -> None:
        raise NotImplementedError


class GeometricObject(PlanObject):
    """A plan object sent as a GEOM (a list of doubles); an empty geometry means "not set"."""

    geometry_size: ClassVar[Optional[int]] = None

    def __init__(self, name: str, geometry: Sequence[float] = ()) -> None:
        super().__init__(name)
        self.geometry: Tuple[float, ...] = tuple(float(v) for v in geometry)

    @property
    def is_geometry_set(self) -> bool:
        """Whether the geometry has the number of values this kind of object needs."""
        return len(self.geometry) == self.geometry_size

    def _write(self, w: Writer) -> None:
        w.i32(len(self.geometry))
        for v in self.geometry:
            w.f64(v)

    @classmethod
    def _read(cls, r: Reader, name: str, field: str) -> "GeometricObject":
        n = r.count(field + " geometry count", codes.MAX_GEOMETRY_DOUBLES)
        return cls(name, [r.f64(f"{field} geometry[{k}]") for k in range(n)])


class _GeometryValue:
    """One value of a plan object's geometry, by position; None while the geometry is not set."""

    def __init__(self, position: int) -> None:
        self.position = position

    def __get__(self, obj: Optional[GeometricObject], owner: type) -> Optional[float]:
        if obj is None or not obj.is_geometry_set:
            return None
        return obj.geometry[self.position]


def _pairs(values: Sequence[float]) -> Tuple[Point, ...]:
    return tuple((values[i], values[i + 1]) for i in range(0, len(values) - 1, 2))


class Wall(GeometricObject):
    """A wall or obstacle: a polygon that stops robots and range sensors and hides targets."""

    type_code = codes.PLAN_WALL
    kind = "wall"

    def __init__(self, name: str, geometry: Sequence[float] = ()) -> None:
        super().__init__(name, geometry)
        self.line_color = Color.DARK_GRAY

    @property
    def is_geometry_set(self) -> bool:
        return len(self.geometry) >= 6 and len(self.geometry) % 2 == 0

    @property
    def vertices(self) -> Tuple[Point, ...]:
        """The polygon's vertices, the first not repeated; empty without a usable geometry."""
        return _pairs(self.geometry) if self.is_geometry_set else ()


class Target(GeometricObject):
    """A point source that target sensors detect (a candle); the radius only sizes its drawing."""

    type_code = codes.PLAN_TARGET
    kind = "target"
    geometry_size = 3

    x = _GeometryValue(0)
    y = _GeometryValue(1)
    radius = _GeometryValue(2)


class Placement(GeometricObject):
    """A named starting pose; the orientation is in radians, exactly as the plan gives it."""

    type_code = codes.PLAN_PLACEMENT
    kind = "placement"
    geometry_size = 4

    def __init__(self, name: str, geometry: Sequence[float] = ()) -> None:
        super().__init__(name, geometry)
        self.fill_color = self.line_color = Color.DARK_GRAY

    x = _GeometryValue(0)
    y = _GeometryValue(1)
    orientation = _GeometryValue(2)
    radius = _GeometryValue(3)


class Paint(GeometricObject):
    """Floor paint for paint sensors: a polygon sent with its first vertex repeated at the end.

    The region code is not on the wire, so a received paint has region 0.
    """

    type_code = codes.PLAN_PAINT
    kind = "paint"

    def __init__(self, name: str, geometry: Sequence[float] = (), fill_color: Optional[Color] = None) -> None:
        super().__init__(name, geometry)
        self.fill_color = fill_color
        self.region = 0

    @property
    def is_geometry_set(self) -> bool:
        return len(self.vertices) >= 3

    @property
    def vertices(self) -> Tuple[Point, ...]:
        """The polygon's vertices without the repeated first one."""
        points = _pairs(self.geometry) if len(self.geometry) % 2 == 0 else ()
        if len(points) > 1 and points[-1] == points[0]:
            points = points[:-1]
        return points

    def _write(self, w: Writer) -> None:
        super()._write(w)
        w.color(self.fill_color)

    @classmethod
    def _read(cls, r: Reader, name: str, field: str) -> "Paint":
        paint = super()._read(r, name, field)
        assert isinstance(paint, Paint)
        paint.fill_color = r.color(field + " fill color")
        return paint


class NavNode(PlanObject):
    """A node of the navigation network; ``links`` are the links attached to it, in plan order."""

    type_code = codes.PLAN_NAV_NODE
    kind = "node"

    def __init__(self, name: str, x: float, y: float, label: Optional[str] = None,
                 color: Optional[Color] = Color.CYAN) -> None:
        super().__init__(name)
        self.x = x
        self.y = y
        self.label = label
        self.fill_color = self.line_color = color
        self.links: List["NavLink"] = []

    def _write(self, w: Writer) -> None:
        w.f64(self.x).f64(self.y).utf(self.label).color(self.line_color)


class NavLink(PlanObject):
    """A link ("road") between two navigation nodes."""

    type_code = codes.PLAN_NAV_LINK
    kind = "link"

    def __init__(self, name: str, node0: NavNode, node1: NavNode, label: Optional[str] = None,
                 color: Optional[Color] = Color.CYAN) -> None:
        super().__init__(name)
        self.node0 = node0
        self.node1 = node1
        self.label = label
        self.fill_color = self.line_color = color

    @property
    def length(self) -> float:
        """Distance between the two nodes, metres."""
        return math.hypot(self.node1.x - self.node0.x, self.node1.y - self.node0.y)

    def other_node(self, node: NavNode) -> Optional[NavNode]:
        """The node at the other end from ``node``, or None if ``node`` is not an end of this link."""
        if node is self.node0:
            return self.node1
        return self.node0 if node is self.node1 else None

    def _write(self, w: Writer) -> None:
        w.utf(self.node0.name).utf(self.node1.name).utf(self.label).color(self.line_color)


T = TypeVar("T", bound=PlanObject)


class _ObjectsOf(Generic[T]):
    """A read-only list attribute of :class:`Plan`: its objects of one class, in plan order."""

    def __init__(self, kind: Type[T]) -> None:
        self.kind = kind

    def __get__(self, plan: "Optional[Plan]", owner: type) -> List[T]:
        if plan is None:
            raise AttributeError(f"objects of {self.kind.__name__} belong to a plan instance")
        return plan.objects_of(self.kind)


class Plan:
    """A floor plan: a caption and its objects in the order of the floor-plan file."""

    def __init__(self, caption: Optional[str] = None) -> None:
        self.caption = caption
        self._objects: List[PlanObject] = []
        self._by_name: Dict[str, PlanObject] = {}

    def add(self, obj: PlanObject) -> None:
        """Appends an object.

        Raises:
            ValueError: if another object already has its name.
        """
        if obj.name in self._by_name:
            raise ValueError(f"duplicate object name {obj.name!r}")
        self._objects.append(obj)
        self._by_name[obj.name] = obj

    def get(self, name: str) -> Optional[PlanObject]:
        """The object called ``name``, or None."""
        return self._by_name.get(name)

    def __getitem__(self, name: str) -> PlanObject:
        return self._by_name[name]

    def __iter__(self) -> Iterator[PlanObject]:
        return iter(self._objects)

    def __len__(self) -> int:
        return len(self._objects)

    def objects_of(self, kind: Type[T]) -> List[T]:
        """The objects of one class, in plan order."""
        return [o for o in self._objects if isinstance(o, kind)]

    walls = _ObjectsOf(Wall)
    targets = _ObjectsOf(Target)
    placements = _ObjectsOf(Placement)
    paints = _ObjectsOf(Paint)
    nav_nodes = _ObjectsOf(NavNode)
    nav_links = _ObjectsOf(NavLink)

    def set_target_selected(self, name: str, selected: bool) -> None:
        """Records a target's selection as a target-selection event reports it."""
        obj = self._by_name.get(name)
        if isinstance(obj, Target):
            obj.selected = selected

    def __repr__(self) -> str:
        return f"Plan({self.caption!r}, {len(self._objects)} objects)"


_GEOMETRIC: Dict[int, Type[GeometricObject]] = {
    codes.PLAN_WALL: Wall, codes.PLAN_TARGET: Target, codes.PLAN_PLACEMENT: Placement, codes.PLAN_PAINT: Paint}


def write_plan(w: Writer, plan: Optional[Plan]) -> None:
    """Appends the encoding of ``plan``; None is "no plan available"."""
    if plan is None:
        w.i32(0)
        return
    w.i32(1).utf(plan.caption).i32(len(plan))
    for obj in plan:
        w.i32(obj.type_code).utf(obj.name)
        obj._write(w)


def read_plan(r: Reader) -> Optional[Plan]:
    """Reads one plan; None if the sender had none."""
    if r.i32("plan available") == 0:
        return None
    plan = Plan(r.utf("plan caption"))
    for i in range(r.count("plan object count", codes.MAX_PLAN_OBJECTS)):
        field = f"plan object[{i}]"
        obj = _read_object(r, plan, field)
        if plan.get(obj.name) is not None:
            raise ProtocolError(field + " name", f'duplicate object name "{obj.name}"')
        plan.add(obj)
    return plan


def _read_object(r: Reader, plan: Plan, field: str) -> PlanObject:
    type_code = r.i32(field + " type")
    name = r.utf(field + " name")
    geometric = _GEOMETRIC.get(type_code)
    if geometric is not None:
        return geometric._read(r, name, field)
    if type_code == codes.PLAN_NAV_NODE:
        x = r.f64(field + " x")
        y = r.f64(field + " y")
        return NavNode(name, x, y, r.utf(field + " label"), r.color(field + " color"))
    if type_code == codes.PLAN_NAV_LINK:
        node0 = _node(plan, r.utf(field + " node0"), field + " node0")
        node1 = _node(plan, r.utf(field + " node1"), field + " node1")
        link = NavLink(name, node0, node1, r.utf(field + " label"), r.color(field + " color"))
        node0.links.append(link)
        node1.links.append(link)
        return link
    raise ProtocolError(field + " type", f"unknown plan object type {type_code}")


def _node(plan: Plan, name: str, field: str) -> NavNode:
    obj = plan.get(name)
    if isinstance(obj, NavNode):
        return obj
    if obj is None:
        raise ProtocolError(field, f'no node called "{name}" was received before this link')
    raise ProtocolError(field, f'"{name}" is a {obj.kind}, not a node')


def encode_plan(plan: Optional[Plan]) -> bytes:
    """The encoding of ``plan`` (None: "no plan available")."""
    w = Writer()
    write_plan(w, plan)
    return w.getvalue()


def decode_plan(data: bytes) -> Optional[Plan]:
    """Decodes bytes that hold exactly one plan encoding.

    Raises:
        ProtocolError: naming the field, if the bytes are not one well-formed plan.
    """
    return read_exactly(data, read_plan, "plan", "the last object")
