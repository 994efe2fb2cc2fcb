"""A robot client's session with the simulator: connection, requests, handlers and the event loop.

The bytes on the wire are the Java library's (``RsClient``), down to the sequence numbers: the
CONNECT carries 0 and the next message 2; a subscription goes out when the first handler of an
(event, sensor) pair is added and an unsubscription on every removal; with the interlock on, every
event is acknowledged after all its handlers have run, even when it has none.
"""

import itertools
import logging
import os
import select
import socket
import struct
import threading
import time
from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple, Type, TypeVar, Union

from . import codes, run
from .body import Body, BodyPart, ContactSensor, PaintSensor, Painter, RangeSensor, Sensor, TargetSensor
from .bodycodec import encode_body
from .errors import ProtocolError
from .events import (EVENT_TYPES, ContactSensorEvent, Event, PaintSensorEvent, RangeSensorEvent, SensorEvent,
                     TargetSensorEvent)
from .messages import HEADER, read_accept, read_event_message
from .requests import (ActuatorControlRequest, EncoderStatusRequest, HaltRequest, HeartbeatRequest, MotionRequest,
                       PainterChangeRequest, PlacementRequest, PlanRequest, PositionRequest, Request,
                       SensorStatusRequest, SubscriptionRequest, TargetSelectionRequest, TimeoutRequest,
                       encode_request)
from .settings import ClientSettings
from .steering import Wheel
from .wire import Reader, require_finite

log = logging.getLogger("rp1client")

E = TypeVar("E", bound=Event)
Handler = Callable[[Any], None]

_I32 = struct.Struct(">i")
_BUFFER_SIZE = 65536
#: How long an incomplete large message waits for more bytes before it is decoded again anyway.
_QUIET_SECONDS = 0.05

#: The body part class whose sensor a sensor event reports.
_SENSOR_CLASSES: Dict[Type[Event], Type[Sensor]] = {
    ContactSensorEvent: ContactSensor, RangeSensorEvent: RangeSensor, TargetSensorEvent: TargetSensor,
    PaintSensorEvent: PaintSensor}


class Client:
    """One robot's session with the RP1 simulator.

    Typical use::

        client = Client("127.0.0.1", 7758).connect()
        client.send_body_specification(body)
        client.add_handler(TimeoutEvent, on_timeout)
        client.send_placement_request("home")
        client.run()

    Without ``host`` or ``port`` the missing one comes from ``RP1_HOST`` and ``RP1_PORT`` when a
    sweep started the program (:mod:`rp1client.run`), else from ``./rossum.ini`` (or the defaults,
    127.0.0.1:7758). Register handlers after :meth:`connect`: a subscription that would be sent
    before the connection exists is skipped, as in the Java library. The ``send_...`` methods may be
    called from any thread; handlers run on the thread that calls :meth:`run`.

    ``max_message_bytes`` bounds the bytes held for one incoming message (by default the Java
    library's limit, 4 MiB): a longer one is a :class:`ProtocolError` naming the field being read.
    """

    def __init__(self, host: Optional[str] = None, port: Optional[int] = None, *,
                 settings: Optional[ClientSettings] = None,
                 max_message_bytes: int = codes.MAX_MESSAGE_BYTES) -> None:
        if isinstance(max_message_bytes, bool) or not isinstance(max_message_bytes, int) or max_message_bytes < 1:
            raise ValueError(f"max_message_bytes must be a positive int, got {max_message_bytes!r}")
        if host is None and port is None and settings is None and run.PORT_VARIABLE in os.environ:
            host = os.environ.get(run.HOST_VARIABLE, "127.0.0.1")
            port = int(os.environ[run.PORT_VARIABLE])
        if host is None or port is None:
            settings = settings or ClientSettings.from_working_directory()
            host = settings.host_name if host is None else host
            port = settings.port if port is None else port
        self.host: str = host
        self.port: int = port
        self._sock: Any = None
        self._send_lock = threading.Lock()
        self._state_lock = threading.Lock()
        self._registry_lock = threading.RLock()
        self._sequence = 0
        self._client_id = 0
        self._client_key = 0
        self._closed = False
        self._stopping = False
        self._handlers: Dict[Tuple[int, int], List[Handler]] = {}
        self._timeout_indexes = itertools.count(1)
        self._encoder_request_indexes = itertools.count(1)
        self._sim_time = 0.0
        self._shutdown_handler: Optional[Callable[[], None]] = None
        self._buf = bytearray(_BUFFER_SIZE)
        self._view = memoryview(self._buf)
        self._start = 0
        self._end = 0
        self.max_message_bytes = max_message_bytes
        self._handshake_deadline: Optional[float] = None

    # ------------------------------------------------------------------------------------------
    # The run (a sweep's --client): parameters, seed and results of the robot's own

    @staticmethod
    def get_run_parameter(name: str) -> Optional[str]:
        """The run's parameter ``name`` (``param.NAME``), or None outside a sweep (:mod:`rp1client.run`)."""
        return run.run_parameter(name)

    @staticmethod
    def get_run_seed() -> int:
        """The run's seed, or 0 outside a sweep."""
        return run.run_seed()

    @staticmethod
    def report_run_result(name: str, value: float) -> None:
        """Reports a result of the robot's own (column ``result.NAME``); the last value wins."""
        run.report_run_result(name, value)

    # ------------------------------------------------------------------------------------------
    # Connection

    def connect(self, timeout: Optional[float] = None) -> "Client":
        """Opens a TCP connection to ``host:port`` and performs the CONNECT/ACCEPT handshake.

        ``timeout`` (seconds) bounds the whole of it: the TCP connection and the server's ACCEPT
        must both arrive within it. None waits for ever. Once connected, reading events is never
        timed out (the simulation may stand still for as long as it likes).

        Returns the client, so that ``Client(...).connect()`` reads naturally.

        Raises:
            ConnectionError: if the server cannot be reached, closes the connection at once, or does
                not complete the handshake within ``timeout``.
            ProtocolError: if its answer is not an ACCEPT.
        """
        deadline = None if timeout is None else time.monotonic() + timeout
        try:
            sock = socket.create_connection((self.host, self.port), timeout=timeout)
        except ConnectionRefusedError as e:
            raise ConnectionError(f"cannot connect to the RP1 server at {self.host}:{self.port}: "
                                  "is it running? start one with rp1") from e
        except OSError as e:
            raise ConnectionError(f"cannot connect to the RP1 server at {self.host}:{self.port}: {e}") from e
        self._handshake_deadline = deadline
        try:
            self.attach(sock)
        except socket.timeout as e:
            sock.close()
            raise ConnectionError(f"the RP1 server at {self.host}:{self.port} did not complete the handshake "
                                  f"(no ACCEPT) within {timeout} s") from e
        except BaseException:
            sock.close()
            raise
        finally:
            self._handshake_deadline = None
        sock.settimeout(None)
        log.info("Connected to RP1 server at %s:%s", self.host, self.port)
        return self

    def attach(self, sock: Any, handshake: bool = True) -> "Client":
        """Talks over an already connected socket (or any object with ``recv_into``, ``sendall``
        and ``close``). Without the handshake both sides start counting messages at 1, as for the
        simulator's in-process clients."""
        try:
            sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        except (OSError, AttributeError):
            pass  # not TCP (a socket pair, a test double): there is no Nagle delay to switch off
        with self._state_lock:
            self._sock = sock
            self._closed = False
        if handshake:
            self._handshake()
        return self

    def _handshake(self) -> None:
        """CONNECT goes out with the sequence number before it is counted, as in RP1 0.60, so it
        carries 0 and the next message 2; the client adopts the id and key the ACCEPT carries."""
        with self._send_lock:
            self._client_id = self._client_key = 0
            self._sock.sendall(HEADER.pack(codes.VERSION, 0, 0, self._sequence, codes.CONNECT))
            self._sequence += 1
        accepted = self._read(read_accept)
        if accepted is None:
            raise ConnectionError(f"the RP1 server at {self.host}:{self.port} closed the connection "
                                  "during the handshake")
        self._client_id, self._client_key, _ = accepted

    @property
    def closed(self) -> bool:
        """Whether the session has ended (closed by either side)."""
        return self._closed

    @property
    def sim_time(self) -> float:
        """The simulation time of the last event received (0 before any; a plan event sets 0)."""
        return self._sim_time

    def set_shutdown_handler(self, handler: Optional[Callable[[], None]]) -> None:
        """A function called once when the session ends, whichever side ends it."""
        self._shutdown_handler = handler

    def close(self) -> None:
        """Ends the session: closes the socket (which also ends a :meth:`run` blocked in another
        thread) and calls the shutdown handler. Further calls do nothing."""
        with self._state_lock:
            if self._closed:
                return
            self._closed = True
            sock = self._sock
        if sock is not None:
            try:
                sock.shutdown(socket.SHUT_RDWR)
            except (OSError, AttributeError):
                pass  # already disconnected; closing is all that is left to do
            sock.close()
        handler = self._shutdown_handler
        if handler is not None:
            handler()

    def __enter__(self) -> "Client":
        return self

    def __exit__(self, *exc_info: object) -> None:
        self.close()

    def _terminate(self, reason: str) -> None:
        if not self._closed:
            log.warning("RP1 session ends: %s", reason)
        self.close()

    # ------------------------------------------------------------------------------------------
    # Handlers

    def add_handler(self, event_type: Type[E], handler: Callable[[E], None],
                    sensor: Union[Sensor, int, None] = None) -> Callable[[E], None]:
        """Calls ``handler(event)`` for every event of ``event_type`` (for sensor events, of
        ``sensor``, given as the part or its id). Returns the handler.

        The first handler of a simulation-generated event (mouse clicks, motion started or halted,
        sensor changes) sends the subscription for it.
        """
        if handler is None:
            raise TypeError("attempt to register None as an event handler")
        key = self._key(event_type, sensor)
        with self._registry_lock:
            if key[0] in codes.SUBSCRIBED_EVENTS and not self._handlers.get(key):
                self._send_subscription(key, True)
            self._handlers.setdefault(key, []).append(handler)
        return handler

    def on(self, event_type: Type[E], sensor: Union[Sensor, int, None] = None) -> Callable[[Handler], Handler]:
        """Decorator form of :meth:`add_handler`: ``@client.on(TimeoutEvent)``."""
        def register(handler: Handler) -> Handler:
            return self.add_handler(event_type, handler, sensor)
        return register

    def remove_handler(self, event_type: Type[E], handler: Callable[[E], None],
                       sensor: Union[Sensor, int, None] = None) -> None:
        """Removes every registration of ``handler`` (a handler added twice is gone after one call).
        For simulation-generated events every removal also sends an unsubscription, even if other
        handlers remain (as RP1 0.60 did); the next handler added then subscribes again."""
        key = self._key(event_type, sensor)
        with self._registry_lock:
            if key[0] in codes.SUBSCRIBED_EVENTS:
                self._send_subscription(key, False)
            handlers = self._handlers.get(key, [])
            handlers[:] = [h for h in handlers if h != handler]

    def remove_handlers(self, event_type: Type[E], sensor: Union[Sensor, int, None] = None) -> None:
        """Removes every handler of ``event_type`` (for sensor events, of ``sensor``), the Java
        library's no-argument ``remove...EventHandler()``; for simulation-generated events it sends
        the unsubscription, and the next handler added subscribes again."""
        key = self._key(event_type, sensor)
        with self._registry_lock:
            if key[0] in codes.SUBSCRIBED_EVENTS:
                self._send_subscription(key, False)
            self._handlers.pop(key, None)

    @staticmethod
    def _key(event_type: Type[Event], sensor: Union[Sensor, int, None]) -> Tuple[int, int]:
        if not (isinstance(event_type, type) and EVENT_TYPES.get(getattr(event_type, "code", -1)) is event_type):
            raise TypeError(f"not an event type: {event_type!r}")
        if not issubclass(event_type, SensorEvent):
            if sensor is not None:
                raise TypeError(f"{event_type.__name__} is not about a sensor; do not pass one")
            return event_type.code, 0
        if sensor is None:
            raise TypeError(f"{event_type.__name__} handlers are registered for one sensor: pass it")
        if isinstance(sensor, BodyPart):
            expected = _SENSOR_CLASSES[event_type]
            if not isinstance(sensor, expected):
                raise TypeError(f"{event_type.__name__} comes from a {expected.__name__}, not {sensor!r}")
            return event_type.code, sensor.id
        return event_type.code, int(sensor)

    def _send_subscription(self, key: Tuple[int, int], enable: bool) -> None:
        if self._sock is not None and not self._closed:
            self.send_request(SubscriptionRequest(key[0], key[1], enable))

    # ------------------------------------------------------------------------------------------
    # Requests

    def send_body_specification(self, body: Body) -> None:
        """Describes the robot to the simulator; send it once, before any request about the robot.

        Raises:
            ValueError: if the body has no part that can be sent, a name is too long, or a dimension
                is NaN or infinite (the message names the part and field; nothing is sent).
        """
        self._send(codes.BODY_SPECIFICATION, encode_body(body, check_finite=True))

    def send_request(self, request: Request) -> None:
        """Sends any request object as it is (the ``send_..._request`` methods build them).

        Raises:
            ValueError: if a string is too long, or a number is NaN or infinite (the message names
                the field, e.g. ``motion rotational velocity``; nothing is sent).
        """
        self._send(codes.REQUEST, encode_request(request, check_finite=True))

    def send_timeout_request(self, duration: float) -> int:
        """Asks for a timeout event after ``duration`` simulated seconds; returns its index
        (1, 2, 3, ...), which the event echoes.

        Raises:
            ValueError: if ``duration`` is NaN or infinite (nothing is sent, no index is used).
        """
        require_finite("duration", duration)
        index = next(self._timeout_indexes)
        self.send_request(TimeoutRequest(duration, index))
        return index

    def send_sensor_status_request(self, sensor: Sensor) -> None:
        """Asks for a sensor's current reading as a sensor event, whatever the subscriptions."""
        self.send_request(SensorStatusRequest(sensor.id))

    def send_motion_request(self, request: MotionRequest) -> None:
        self.send_request(request)

    def send_halt_request(self) -> None:
        self.send_request(HaltRequest())

    def send_position_request(self) -> None:
        self.send_request(PositionRequest())

    def send_placement_request(self, name: Optional[str] = None) -> None:
        """Asks to be put at the named placement; None or "" for any, "$random" for a free pose."""
        self.send_request(PlacementRequest(name))

    def send_target_selection_request(self, target_name: str, status: bool) -> None:
        self.send_request(TargetSelectionRequest(False, target_name, status, False))

    def send_exclusive_target_selection_request(self, target_name: str) -> None:
        self.send_request(TargetSelectionRequest(False, target_name, True, True))

    def send_random_target_selection_request(self, status: bool) -> None:
        self.send_request(TargetSelectionRequest(True, None, status, False))

    def send_exclusive_random_target_selection_request(self) -> None:
        self.send_request(TargetSelectionRequest(True, None, True, True))

    def send_all_targets_selection_request(self, status: bool) -> None:
        self.send_request(TargetSelectionRequest(False, "*", status, False))

    def send_plan_request(self) -> None:
        self.send_request(PlanRequest())

    def send_heartbeat_request(self, interval: float) -> None:
        """Asks for a heartbeat event every ``interval`` simulated seconds (0 cancels; the server
        raises an interval below 1 ms to 1 ms).

        Raises:
            ValueError: if ``interval`` is NaN or infinite (nothing is sent).
        """
        require_finite("interval", interval)
        self.send_request(HeartbeatRequest(interval))

    def send_heartbeat_cancellation_request(self) -> None:
        self.send_request(HeartbeatRequest(0.0))

    def send_painter_activation_request(self, painter: Painter) -> None:
        """Starts the painter's trail. A painter without a colour or a trailer cannot paint, so a
        deactivation is sent instead."""
        if not painter.paint_colors or not painter.trailer_defined:
            self.send_painter_deactivation_request(painter)
            return
        painter.active = True
        self.send_request(PainterChangeRequest(painter.id, False, True, True, painter.trailer_x, painter.trailer_y,
                                               painter.trailer_width, painter.paint_colors))

    def send_painter_deactivation_request(self, painter: Painter) -> None:
        painter.active = False
        self.send_request(PainterChangeRequest(painter.id))

    def send_painter_erasure_request(self, painter: Painter) -> None:
        self.send_request(PainterChangeRequest(painter.id, erasure=True))

    def send_actuator_control_request(self, request: ActuatorControlRequest) -> None:
        """Sends an actuator command. Without parameters the simulator has nothing to apply: a HALT
        goes out as a halt request, any other command is dropped with a log line."""
        if request.parameters:
            self.send_request(request)
        elif request.command_id == ActuatorControlRequest.HALT:
            self.send_halt_request()
        else:
            log.info("actuator command %d without parameters not sent", request.command_id)

    def send_encoder_status_request(self, encoders: Union[Wheel, Sequence[Wheel], None],
                                    clear_on_report: bool = False) -> int:
        """Asks for the state of these encoders (wheels), one event each, in order. Returns the
        request's index (1, 2, 3, ...), or -1 and sends nothing if any encoder is None."""
        if encoders is None:
            return -1
        wheels = [encoders] if isinstance(encoders, Wheel) else list(encoders)
        if any(w is None for w in wheels):
            return -1
        index = next(self._encoder_request_indexes)
        self.send_request(EncoderStatusRequest(index, tuple(w.id for w in wheels), clear_on_report))
        return index

    def _send(self, transaction: int, payload: bytes) -> None:
        """Sends one whole message with the next sequence number in one call. After the session has
        ended messages are dropped; before it was ever connected they are a mistake."""
        with self._send_lock:
            if self._closed:
                log.debug("session closed, %s not sent", codes.TRANSACTION_NAMES[transaction])
                return
            if self._sock is None:
                raise RuntimeError("the client is not connected: call connect() before sending")
            self._sequence += 1
            message = HEADER.pack(codes.VERSION, self._client_id, self._client_key, self._sequence,
                                  transaction) + payload
            try:
                self._sock.sendall(message)
                return
            except OSError as e:
                failure = e
        self._terminate(f"output failure: {failure}")

    # ------------------------------------------------------------------------------------------
    # Event loop

    def run(self, until: Optional[float] = None) -> None:
        """Reads events and calls their handlers until the server closes the connection, until
        :meth:`stop` is called, or, with ``until``, until an event stamped ``until`` or later has
        been handled. With the interlock on, each event is acknowledged after its handlers.

        A handler that raises is logged and the event goes on to the remaining handlers (an
        exception escaping here would leave the simulation waiting for the acknowledgement).

        Raises:
            ProtocolError: if the server breaks the protocol; the session is closed first.
        """
        if self._sock is None:
            raise RuntimeError("the client is not connected: call connect() before run()")
        self._stopping = False
        while not self._stopping and not self._closed:
            try:
                item = self._read(self._read_event)
            except ProtocolError as e:
                self._terminate(str(e))
                raise
            except OSError as e:
                self._terminate(f"input failure: {e}")
                return
            if item is None:
                self._terminate("the server closed the connection")
                return
            event, interlock = item
            self._dispatch(event)
            if interlock > 0:
                self._send(codes.INTERLOCK, _I32.pack(interlock))
            if until is not None and event.sim_time >= until:
                return

    def stop(self) -> None:
        """Makes :meth:`run` return after the event being handled (call it from a handler, or from
        another thread, where it takes effect after the next event; :meth:`close` ends at once)."""
        self._stopping = True

    def _read_event(self, r: Reader) -> Tuple[Event, int]:
        event, interlock, _ = read_event_message(r, self._client_id, self._client_key)
        self._sim_time = event.sim_time
        return event, interlock

    def _dispatch(self, event: Event) -> None:
        handlers = self._handlers.get((event.code, event.index))
        if not handlers:
            return
        for handler in tuple(handlers):
            if event.consumed:
                return
            try:
                handler(event)
            except Exception:
                log.exception("handler %r failed on %r", handler, event)

    def _read(self, decode: Callable[[Reader], Any]) -> Any:
        """Decodes one message from the buffered input, reading more until it is complete.
        Returns None if the stream ended cleanly before the message's first byte.

        An incomplete message is decoded again from its start, so a large one is retried only when
        its bytes have doubled or the stream has gone quiet: the work stays linear in its size.

        Raises:
            ProtocolError: if the message is malformed, or longer than ``max_message_bytes``
                (naming the field that crosses the limit).
        """
        retry_at = 0
        while True:
            buffered = self._end - self._start
            if buffered and (buffered >= retry_at or not self._more_coming()):
                r = Reader(self._buf, self._start, self._start + min(buffered, self.max_message_bytes))
                try:
                    result = decode(r)
                except ProtocolError as e:
                    if not e.truncated:
                        raise
                    if buffered >= self.max_message_bytes:
                        raise ProtocolError(e.field, f"message longer than {self.max_message_bytes} bytes "
                                                     "(max_message_bytes)") from None
                    retry_at = min(2 * buffered, self.max_message_bytes) if buffered >= _BUFFER_SIZE else 0
                    if not self._fill():
                        if self._closed:
                            return None
                        raise
                    continue
                self._start = r.pos
                return result
            if not self._fill():
                if not buffered:
                    return None
                retry_at = 0

    def _more_coming(self) -> bool:
        """Whether more bytes arrive within a moment (False for a socket double that cannot tell)."""
        try:
            readable, _, _ = select.select([self._sock], [], [], _QUIET_SECONDS)
        except (TypeError, ValueError, OSError):
            return False
        return bool(readable)

    def _fill(self) -> bool:
        """Reads what the socket has into the buffer, after the unread bytes; False at end of stream."""
        start, end = self._start, self._end
        if start == end:
            start = end = 0
        elif start > 0:
            self._buf[0:end - start] = self._buf[start:end]
            start, end = 0, end - start
        self._start, self._end = start, end
        if end == len(self._buf):
            self._view.release()
            self._buf.extend(bytes(len(self._buf)))
            self._view = memoryview(self._buf)
        sock = self._sock
        if sock is None or self._closed:
            return False
        if self._handshake_deadline is not None:
            remaining = self._handshake_deadline - time.monotonic()
            if remaining <= 0:
                raise socket.timeout("handshake deadline passed")
            sock.settimeout(remaining)
        n = sock.recv_into(self._view[end:])
        if n == 0:
            return False
        self._end = end + n
        return True
