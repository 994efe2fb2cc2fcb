"""The primitive encodings of RP1 (docs/protocol.md section 2), over byte buffers and without sockets.

:class:`Reader` reads named fields from a buffer and raises :class:`~rp1client.errors.ProtocolError`
naming the field on any problem; :class:`Writer` builds one message in memory. :class:`Record`
describes a run of fields by kind, attribute and name, so that events and requests are declared
once and read and written from the same declaration.
"""

import math
import struct
from dataclasses import dataclass
from typing import Any, Callable, ClassVar, Dict, List, Optional, Sequence, Tuple, TypeVar, Union

from .codes import MAX_COLORS
from .errors import ProtocolError

Buffer = Union[bytes, bytearray, memoryview]

_I32 = struct.Struct(">i")
_F64 = struct.Struct(">d")
_U16 = struct.Struct(">H")
_COLOR = struct.Struct(">iiii")

ENDED = "stream ended in the middle of a message"
MAX_STR_BYTES = 65535


@dataclass(frozen=True)
class Color:
    """An opaque RGB colour; each component is 0..255 (the wire has no alpha)."""

    red: int
    green: int
    blue: int

    WHITE: ClassVar["Color"]
    BLACK: ClassVar["Color"]
    LIGHT_GRAY: ClassVar["Color"]
    GRAY: ClassVar["Color"]
    DARK_GRAY: ClassVar["Color"]
    RED: ClassVar["Color"]
    GREEN: ClassVar["Color"]
    BLUE: ClassVar["Color"]
    YELLOW: ClassVar["Color"]
    ORANGE: ClassVar["Color"]
    CYAN: ClassVar["Color"]
    MAGENTA: ClassVar["Color"]
    PINK: ClassVar["Color"]

    def __post_init__(self) -> None:
        for name in ("red", "green", "blue"):
            value = getattr(self, name)
            if not isinstance(value, int) or not 0 <= value <= 255:
                raise ValueError(f"Color {name} must be an int in 0..255, got {value!r}")


# The values of java.awt.Color's constants, which the Java library's defaults use.
Color.WHITE = Color(255, 255, 255)
Color.BLACK = Color(0, 0, 0)
Color.LIGHT_GRAY = Color(192, 192, 192)
Color.GRAY = Color(128, 128, 128)
Color.DARK_GRAY = Color(64, 64, 64)
Color.RED = Color(255, 0, 0)
Color.GREEN = Color(0, 255, 0)
Color.BLUE = Color(0, 0, 255)
Color.YELLOW = Color(255, 255, 0)
Color.ORANGE = Color(255, 200, 0)
Color.CYAN = Color(0, 255, 255)
Color.MAGENTA = Color(255, 0, 255)
Color.PINK = Color(255, 175, 175)


def encode_modified_utf8(text: str) -> bytes:
    """Java's modified UTF-8: U+0000 as ``c0 80``, characters beyond U+FFFF as two 3-byte surrogates."""
    if text.isascii() and "\0" not in text:
        return text.encode("ascii")
    out = bytearray()
    for ch in text:
        cp = ord(ch)
        if cp == 0:
            out += b"\xc0\x80"
        elif cp < 0x10000:
            out += ch.encode("utf-8", "surrogatepass")
        else:
            cp -= 0x10000
            out += chr(0xD800 | (cp >> 10)).encode("utf-8", "surrogatepass")
            out += chr(0xDC00 | (cp & 0x3FF)).encode("utf-8", "surrogatepass")
    return bytes(out)


def decode_modified_utf8(data: bytes, field: str) -> str:
    """Decodes what Java's ``readUTF`` accepts: 1-, 2- and 3-byte forms of UTF-16 code units.

    Surrogate pairs become one character; an unpaired surrogate stays as it is, as in Java.
    """
    if data.isascii():
        return data.decode("ascii")
    units: List[int] = []
    i, n = 0, len(data)
    while i < n:
        b = data[i]
        if b < 0x80:
            units.append(b)
            i += 1
        elif b >> 5 == 0b110:
            _check_continuation(data, i, 2, field)
            units.append(((b & 0x1F) << 6) | (data[i + 1] & 0x3F))
            i += 2
        elif b >> 4 == 0b1110:
            _check_continuation(data, i, 3, field)
            units.append(((b & 0x0F) << 12) | ((data[i + 1] & 0x3F) << 6) | (data[i + 2] & 0x3F))
            i += 3
        else:
            raise ProtocolError(field, f"invalid modified UTF-8 (malformed input around byte {i})")
    text = "".join(map(chr, units))
    return text.encode("utf-16-be", "surrogatepass").decode("utf-16-be", "surrogatepass")


def _check_finite(field: str, value: float) -> None:
    if not math.isfinite(value):
        raise ProtocolError(field, f"{value!r} is not a finite number")


def require_finite(argument: str, value: float) -> None:
    """Raises ValueError unless ``value`` is a finite number: the server drops a client that sends
    NaN or an infinity (docs/protocol.md section 14)."""
    if not math.isfinite(value):
        raise ValueError(f"{argument} must be a finite number, got {value!r}")


def require_finite_fields(what: str, data: bytes, read: Callable[["Reader"], object]) -> None:
    """Raises ValueError naming the field if ``read`` finds NaN or an infinity in ``data``, the
    encoding of a request or a body about to be sent."""
    try:
        read(Reader(data, finite=True))
    except ProtocolError as e:
        raise ValueError(what + str(e)) from None


def _check_continuation(data: bytes, i: int, length: int, field: str) -> None:
    if i + length > len(data):
        raise ProtocolError(field, "invalid modified UTF-8 (malformed input: partial character at end)")
    for k in range(i + 1, i + length):
        if data[k] & 0xC0 != 0x80:
            raise ProtocolError(field, f"invalid modified UTF-8 (malformed input around byte {k})")


class Reader:
    """Reads RP1 fields from ``buf[pos:end]``; every method names the field it reads.

    Running out of bytes raises a :class:`ProtocolError` with ``truncated`` set, so that a caller
    reading from a stream can wait for more bytes and try the message again. With ``finite`` set,
    an f64 that is NaN or infinite is a :class:`ProtocolError` too, as the server has it for what a
    client sends (docs/protocol.md section 14).
    """

    __slots__ = ("buf", "pos", "end", "finite")

    def __init__(self, buf: Buffer, pos: int = 0, end: Optional[int] = None, finite: bool = False) -> None:
        self.buf = buf
        self.pos = pos
        self.end = len(buf) if end is None else end
        self.finite = finite

    @property
    def remaining(self) -> int:
        """Bytes not yet read."""
        return self.end - self.pos

    def _take(self, n: int, field: str) -> int:
        p = self.pos
        if p + n > self.end:
            raise ProtocolError(field, ENDED, truncated=True)
        self.pos = p + n
        return p

    def unpack(self, layout: struct.Struct, field: str) -> Tuple[Any, ...]:
        """Reads a fixed layout at once; ``field`` names it if the bytes run out."""
        return layout.unpack_from(self.buf, self._take(layout.size, field))

    def i32(self, field: str) -> int:
        return _I32.unpack_from(self.buf, self._take(4, field))[0]

    def f64(self, field: str) -> float:
        value: float = _F64.unpack_from(self.buf, self._take(8, field))[0]
        if self.finite:
            _check_finite(field, value)
        return value

    def boolean(self, field: str) -> bool:
        """Any non-zero byte is true, as Java's ``readBoolean`` has it."""
        return self.buf[self._take(1, field)] != 0

    def utf(self, field: str) -> str:
        """A STR: unsigned 16-bit byte count, then modified UTF-8; never None."""
        n = _U16.unpack_from(self.buf, self._take(2, field))[0]
        p = self._take(n, field)
        return decode_modified_utf8(bytes(self.buf[p:p + n]), field)

    def count(self, field: str, limit: int) -> int:
        """A non-negative i32 count no larger than ``limit``."""
        n = self.i32(field)
        if n < 0 or n > limit:
            raise ProtocolError(field, f"{n} is outside the accepted range 0..{limit}")
        return n

    def color(self, field: str) -> Optional[Color]:
        """A COLOR: an i32 presence flag (0 = none), then red, green and blue in 0..255."""
        if self.i32(field + " present") == 0:
            return None
        rgb = []
        for name in ("red", "green", "blue"):
            value = self.i32(f"{field} {name}")
            if not 0 <= value <= 255:
                raise ProtocolError(f"{field} {name}", f"{value} is outside 0..255")
            rgb.append(value)
        return Color(*rgb)

    def color_array(self, field: str) -> Optional[Tuple[Optional[Color], ...]]:
        """A COLOR_ARRAY: an i32 count (0 = none), then that many COLORs."""
        n = self.count(field + " count", MAX_COLORS)
        if n == 0:
            return None
        return tuple(self.color(f"{field}[{i}]") for i in range(n))

    def points(self, field: str, limit: int) -> Tuple[Tuple[float, float], ...]:
        """A SEGLIST: an i32 vertex count, then x, y of each vertex."""
        n = self.count(field + " count", limit)
        return tuple((self.f64(f"{field}[{i}].x"), self.f64(f"{field}[{i}].y")) for i in range(n))


class Writer:
    """Builds one message in memory, so nothing half-encoded can reach a stream.

    ``finite`` stays true while every f64 written is a finite number: a message about to be sent is
    only decoded again, to name the field, when it is false.
    """

    __slots__ = ("data", "finite")

    def __init__(self) -> None:
        self.data = bytearray()
        self.finite = True

    def getvalue(self) -> bytes:
        return bytes(self.data)

    def pack(self, layout: struct.Struct, *values: Any) -> "Writer":
        self.data += layout.pack(*values)
        return self

    def i32(self, value: int) -> "Writer":
        self.data += _I32.pack(value)
        return self

    def f64(self, value: float) -> "Writer":
        self.data += _F64.pack(value)
        if not math.isfinite(value):
            self.finite = False
        return self

    def boolean(self, value: bool) -> "Writer":
        self.data.append(1 if value else 0)
        return self

    def utf(self, text: Optional[str]) -> "Writer":
        """A STR; None is sent as the empty string.

        Raises:
            ValueError: if the text needs more than 65535 bytes of modified UTF-8.
        """
        data = encode_modified_utf8(text or "")
        if len(data) > MAX_STR_BYTES:
            raise ValueError(f"string too long for the RP1 wire format (limit {MAX_STR_BYTES} bytes): "
                             f"{(text or '')[:40]!r}...")
        self.data += _U16.pack(len(data))
        self.data += data
        return self

    def color(self, color: Optional[Color]) -> "Writer":
        if color is None:
            return self.i32(0)
        self.data += _COLOR.pack(1, color.red, color.green, color.blue)
        return self

    def color_array(self, colors: Optional[Sequence[Optional[Color]]]) -> "Writer":
        """None or an empty list is sent as count 0."""
        if not colors:
            return self.i32(0)
        self.i32(len(colors))
        for c in colors:
            self.color(c)
        return self

    def points(self, points: Sequence[Tuple[float, float]]) -> "Writer":
        self.i32(len(points))
        for x, y in points:
            self.f64(x).f64(y)
        return self


#: Field kinds of a :class:`Record`: struct codes, plus "s" for a STR.
_KINDS = {"i": "i", "d": "d", "?": "?", "s": None}

V = TypeVar("V")


def read_exactly(data: Buffer, read: Callable[[Reader], V], field: str, last: str) -> V:
    """Reads one value from ``data`` with ``read``; bytes left over after it are a protocol error
    (``FIELD: N bytes left over after LAST``)."""
    r = Reader(data)
    value = read(r)
    if r.remaining:
        raise ProtocolError(field, f"{r.remaining} bytes left over after {last}")
    return value


class Record:
    """A fixed sequence of fields, each ``(kind, attribute, wire name)``.

    Kinds are ``"i"`` (i32), ``"d"`` (f64), ``"?"`` (bool) and ``"s"`` (STR). Runs of fixed-size
    fields are read with one precompiled struct when the bytes are there, and field by field when
    they are not, so that a truncation names the first missing field.
    """

    def __init__(self, *fields: Tuple[str, str, str]) -> None:
        for kind, _, _ in fields:
            if kind not in _KINDS:
                raise ValueError(f"unknown field kind {kind!r}")
        self.attributes = tuple(attr for _, attr, _ in fields)
        self._runs: List[Tuple[Optional[struct.Struct], Tuple[Tuple[str, str, str], ...]]] = []
        #: Per run, the attributes of its f64 fields, whose finiteness :meth:`write` notes.
        self._reals: List[Tuple[str, ...]] = []
        run: List[Tuple[str, str, str]] = []
        for f in fields:
            if f[0] == "s":
                self._flush(run)
                self._runs.append((None, (f,)))
                self._reals.append(())
            else:
                run.append(f)
        self._flush(run)

    def _flush(self, run: List[Tuple[str, str, str]]) -> None:
        if run:
            self._runs.append((struct.Struct(">" + "".join(k for k, _, _ in run)), tuple(run)))
            self._reals.append(tuple(attr for kind, attr, _ in run if kind == "d"))
            run.clear()

    def read(self, r: Reader) -> Dict[str, Any]:
        values: Dict[str, Any] = {}
        for layout, fields in self._runs:
            if layout is None:
                _, attr, name = fields[0]
                values[attr] = r.utf(name)
            elif r.end - r.pos >= layout.size:
                values.update(zip((a for _, a, _ in fields), r.unpack(layout, fields[0][2])))
                if r.finite:
                    for kind, attr, name in fields:
                        if kind == "d":
                            _check_finite(name, values[attr])
            else:
                for kind, attr, name in fields:
                    values[attr] = r.i32(name) if kind == "i" else r.f64(name) if kind == "d" else r.boolean(name)
        return values

    def write(self, w: Writer, source: Any) -> None:
        """Writes the attributes of ``source`` in wire order."""
        for (layout, fields), reals in zip(self._runs, self._reals):
            if layout is None:
                w.utf(getattr(source, fields[0][1]))
            else:
                w.pack(layout, *(getattr(source, attr) for _, attr, _ in fields))
                if w.finite and not all(math.isfinite(getattr(source, attr)) for attr in reals):
                    w.finite = False
