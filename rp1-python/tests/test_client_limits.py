"""The client's bounds against a server that misbehaves: the handshake is bounded by the connect
timeout, and no message may hold more than ``max_message_bytes`` (the Java library's limit). Each
test talks to a fake server on a loopback port and ends in seconds."""

import re
import socket
import struct
import threading
from typing import Callable, Iterator

import pytest

import rp1client as rp
from rp1client import codes
from rp1client.messages import HEADER
from support import REPO_ROOT

#: How long a fake server keeps a silent connection open: long enough that a client without a
#: handshake bound sees the close instead of its own timeout.
SILENCE_SECONDS = 10.0


class FakeServer:
    """Accepts one connection on a loopback port and hands it to ``script`` on a thread of its own."""

    def __init__(self, script: Callable[[socket.socket], None]) -> None:
        self.listener = socket.create_server(("127.0.0.1", 0))
        self.port = self.listener.getsockname()[1]
        self.done = threading.Event()
        self.thread = threading.Thread(target=self._serve, args=(script,), daemon=True)
        self.thread.start()

    def _serve(self, script: Callable[[socket.socket], None]) -> None:
        conn, _ = self.listener.accept()
        with conn:
            try:
                script(conn)
            except OSError:
                pass  # the client hung up: the script's work is over

    def close(self) -> None:
        self.done.set()
        self.listener.close()
        self.thread.join(SILENCE_SECONDS + 5)


@pytest.fixture
def serve() -> Iterator[Callable[[Callable[[socket.socket], None]], FakeServer]]:
    servers = []

    def start(script: Callable[[socket.socket], None]) -> FakeServer:
        servers.append(FakeServer(script))
        return servers[-1]

    yield start
    for s in servers:
        s.close()


def read_exactly(conn: socket.socket, n: int) -> bytes:
    data = b""
    while len(data) < n:
        chunk = conn.recv(n - len(data))
        if not chunk:
            raise OSError("client left")
        data += chunk
    return data


def accept(conn: socket.socket) -> None:
    """Reads the CONNECT and answers it with an ACCEPT for client 0, key 0."""
    read_exactly(conn, HEADER.size)
    conn.sendall(HEADER.pack(codes.VERSION, 0, 0, 1, codes.ACCEPT))


def plan_event_start(geometry_count: int) -> bytes:
    """An EVENT carrying a plan whose one wall announces ``geometry_count`` doubles (not included)."""
    name = b"w"
    return (HEADER.pack(codes.VERSION, 0, 0, 2, codes.EVENT)
            + struct.pack(">iidi", codes.EVT_PLAN, 0, 0.0, 0)
            + struct.pack(">iH", 1, 0) + struct.pack(">i", 1)
            + struct.pack(">iH", codes.PLAN_WALL, len(name)) + name + struct.pack(">i", geometry_count))


def events_until(server: FakeServer, event_type: type, until: float, timeout: float) -> list:
    """Connects, runs until an event stamped ``until`` and returns the events of ``event_type``."""
    client = rp.Client("127.0.0.1", server.port).connect(timeout=timeout)
    seen: list = []
    client.add_handler(event_type, seen.append)
    client.run(until=until)
    client.close()
    return seen


def test_the_connect_timeout_bounds_the_handshake_against_a_server_that_never_answers(serve) -> None:
    server = serve(lambda conn: server.done.wait(SILENCE_SECONDS))
    with pytest.raises(ConnectionError, match=r"did not complete the handshake \(no ACCEPT\) within 0.5 s"):
        rp.Client("127.0.0.1", server.port).connect(timeout=0.5)


def test_the_connect_timeout_bounds_the_whole_handshake_not_each_read(serve) -> None:
    def trickle(conn: socket.socket) -> None:
        read_exactly(conn, HEADER.size)
        for byte in HEADER.pack(codes.VERSION, 0, 0, 1, codes.ACCEPT)[:-1]:
            conn.sendall(bytes([byte]))
            if server.done.wait(0.2):
                return
        server.done.wait(SILENCE_SECONDS)

    server = serve(trickle)
    with pytest.raises(ConnectionError, match="did not complete the handshake"):
        rp.Client("127.0.0.1", server.port).connect(timeout=1.0)


def test_after_the_handshake_reads_are_not_timed_out(serve) -> None:
    def slow_event(conn: socket.socket) -> None:
        accept(conn)
        server.done.wait(0.8)
        conn.sendall(HEADER.pack(codes.VERSION, 0, 0, 2, codes.EVENT) + rp.encode_event(rp.TimeoutEvent(1.0, 1)))
        server.done.wait(SILENCE_SECONDS)

    server = serve(slow_event)
    assert [e.sim_time for e in events_until(server, rp.TimeoutEvent, 1.0, timeout=0.5)] == [1.0]


def test_a_message_beyond_the_size_limit_is_refused_naming_the_field_it_reached(serve) -> None:
    doubles = codes.MAX_MESSAGE_BYTES // 8 + 8192

    def huge_plan(conn: socket.socket) -> None:
        accept(conn)
        conn.sendall(plan_event_start(doubles))
        chunk = bytes(8 * 8192)
        for _ in range(doubles // 8192):
            conn.sendall(chunk)
        server.done.wait(SILENCE_SECONDS)

    server = serve(huge_plan)
    client = rp.Client("127.0.0.1", server.port).connect(timeout=5)
    with pytest.raises(rp.ProtocolError) as caught:
        client.run()
    assert caught.value.field == "plan object[0] geometry[524280]"
    assert caught.value.problem == f"message longer than {codes.MAX_MESSAGE_BYTES} bytes (max_message_bytes)"
    assert client.closed


def test_a_large_message_within_the_limit_arrives_whole_in_pieces_with_pauses(serve) -> None:
    doubles = 200_000

    def paced_plan(conn: socket.socket) -> None:
        accept(conn)
        data = plan_event_start(doubles) + struct.pack(f">{doubles}d", *range(doubles))
        for at in range(0, len(data), 100_000):
            conn.sendall(data[at:at + 100_000])
            server.done.wait(0.01)
        server.done.wait(SILENCE_SECONDS)

    server = serve(paced_plan)
    plans = events_until(server, rp.PlanEvent, 0.0, timeout=5)
    assert plans[0].plan.get("w").geometry[-1] == doubles - 1


def test_the_limit_can_be_set_per_client_and_must_be_positive(serve) -> None:
    def plan_of_2000_bytes(conn: socket.socket) -> None:
        accept(conn)
        conn.sendall(plan_event_start(250) + bytes(2000))
        server.done.wait(SILENCE_SECONDS)

    server = serve(plan_of_2000_bytes)
    client = rp.Client("127.0.0.1", server.port, max_message_bytes=1000).connect(timeout=5)
    with pytest.raises(rp.ProtocolError, match="message longer than 1000 bytes"):
        client.run()
    with pytest.raises(ValueError, match="max_message_bytes must be a positive int"):
        rp.Client("h", 1, max_message_bytes=0)


def test_the_default_limit_is_the_java_librarys() -> None:
    source = (REPO_ROOT / "rp1-rossum" / "src" / "main" / "java" / "rp1" / "rossum" / "wire" / "WireLimits.java").read_text()
    java = re.search(r"MAX_MESSAGE_BYTES = (\d+) << (\d+);", source)
    assert java is not None, "WireLimits.MAX_MESSAGE_BYTES is no longer written as A << B"
    assert codes.MAX_MESSAGE_BYTES == int(java.group(1)) << int(java.group(2))
