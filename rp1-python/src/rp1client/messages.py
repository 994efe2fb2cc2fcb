"""Whole messages: the 20-byte transaction header, the handshake, and events as a client reads them
(docs/protocol.md sections 3 and 4). Socket-free: everything works on byte buffers."""

import struct
from typing import Tuple

from . import codes
from .errors import ProtocolError
from .events import EVENT_TYPES, Event, read_event, read_event_body
from .wire import Reader

HEADER = struct.Struct(">iiiii")
#: A header followed by the event prefix (code, index, simTime, interlock): 40 bytes.
_EVENT_START = struct.Struct(">iiiiiiidi")
_EVENT_START_SIZE = _EVENT_START.size


def header(client_id: int, client_key: int, sequence: int, transaction: int) -> bytes:
    """The 20-byte header: version 0, client id, client key, sequence number, transaction code."""
    return HEADER.pack(codes.VERSION, client_id, client_key, sequence, transaction)


def read_header(r: Reader, client_id: int, client_key: int) -> Tuple[int, int]:
    """Reads and checks a header after the handshake (section 3.2): version 0, the agreed client id
    and key, a code in 1..6. Returns (sequence, transaction code)."""
    version = r.i32("header version")
    if version != codes.VERSION:
        raise ProtocolError("header version", f"expected {codes.VERSION}, got {version}")
    got_id = r.i32("header client id")
    if got_id != client_id:
        raise ProtocolError("header client id", f"expected {client_id}, got {got_id}")
    got_key = r.i32("header client key")
    if got_key != client_key:
        raise ProtocolError("header client key", f"expected {client_key}, got {got_key}")
    sequence = r.i32("header sequence")
    code = r.i32("header transaction code")
    if not codes.CONNECT <= code <= codes.INTERLOCK:
        raise ProtocolError("header transaction code", f"unknown code {code}")
    return sequence, code


def read_accept(r: Reader) -> Tuple[int, int, int]:
    """Reads the server's ACCEPT; returns the client id, client key and sequence it carries."""
    version = r.i32("ACCEPT version")
    if version != codes.VERSION:
        raise ProtocolError("ACCEPT version", f"expected {codes.VERSION}, got {version}")
    client_id = r.i32("ACCEPT client id")
    client_key = r.i32("ACCEPT client key")
    sequence = r.i32("ACCEPT sequence")
    code = r.i32("ACCEPT transaction code")
    if code != codes.ACCEPT:
        raise ProtocolError("ACCEPT transaction code", f"expected ACCEPT (2), got {codes.describe_transaction(code)}")
    return client_id, client_key, sequence


def read_event_message(r: Reader, client_id: int, client_key: int) -> Tuple[Event, int, int]:
    """Reads one whole EVENT message; returns the event, its interlock number and its sequence.

    The common case (a valid header and a known event code) is read with one struct; anything
    else goes field by field, which names the field at fault.
    """
    if r.end - r.pos >= _EVENT_START_SIZE:
        version, got_id, got_key, sequence, transaction, code, index, sim_time, interlock = \
            _EVENT_START.unpack_from(r.buf, r.pos)
        if (version == codes.VERSION and got_id == client_id and got_key == client_key
                and transaction == codes.EVENT and code in EVENT_TYPES):
            r.pos += _EVENT_START_SIZE
            return read_event_body(r, code, index, sim_time), interlock, sequence
    sequence, transaction = read_header(r, client_id, client_key)
    if transaction != codes.EVENT:
        raise ProtocolError("header transaction code",
                            f"a client accepts only EVENT (3), got {codes.describe_transaction(transaction)}")
    event, interlock = read_event(r)
    return event, interlock, sequence
