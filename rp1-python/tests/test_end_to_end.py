"""Python robots against our simulator, started from the built jars (see conftest.py)."""

import math
import re
import signal
import socket
import subprocess
import sys
import threading
import time
from typing import Callable, Dict, List, Optional

import pytest

import rp1client as rp
from rp1client.simulator import LocalSimulator
from support import REPO_ROOT

EXAMPLES_DIR = REPO_ROOT / "rp1-python" / "examples"
#: Wall-clock seconds any one run may take before the test gives up on it.
LIMIT = 30.0


def run(client: rp.Client, until: Optional[float] = None) -> None:
    """``client.run(until)``, closed by a watchdog if the simulation stalls."""
    watchdog = threading.Timer(LIMIT, client.close)
    watchdog.start()
    try:
        client.run(until)
    finally:
        watchdog.cancel()
    assert not (client.closed and until is not None), "the session ended before the simulated time"


class Probe:
    """A 0.1 m round robot with a front bumper, a 0.5 m range sensor in 5 bins and encoders."""

    def __init__(self, client: rp.Client) -> None:
        self.client = client
        self.body = rp.Body("probe")
        self.steering = rp.DifferentialSteering(0.2, 0.05)
        self.steering.add_default_wheels(0.05, 0.02)
        self.encoders = self.steering.add_encoders_to_default_wheels(100)
        self.body.add_part(self.steering)
        self.body.add_part(rp.Circle(0.0, 0.0, 0.1))
        self.bumper = rp.ContactSensor([(0.05, -0.08), (0.11, -0.03), (0.11, 0.03), (0.05, 0.08)])
        self.sonar = rp.RangeSensor([(0.0, -0.02), (0.1, 0.0), (0.0, 0.02)], 0.1, 0.0, 0.0, 0.5, 5)
        self.body.add_part(self.bumper)
        self.body.add_part(self.sonar)
        self.events: List[rp.Event] = []
        client.send_body_specification(self.body)

    def record(self, *event_types: type) -> None:
        for event_type in event_types:
            sensor = {rp.ContactSensorEvent: self.bumper, rp.RangeSensorEvent: self.sonar}.get(event_type)
            self.client.add_handler(event_type, self.events.append, sensor)

    def of(self, event_type: type) -> List:
        return [e for e in self.events if isinstance(e, event_type)]


def place(client: rp.Client, name: str, then: Callable[[], object] = lambda: None) -> rp.PlacementEvent:
    """Places the robot; ``then`` runs in the placement's handler, while the interlock holds the
    clock, so that what it asks for starts at the time of the placement."""
    placements: List[rp.PlacementEvent] = []
    client.add_handler(rp.PlacementEvent, lambda e: (placements.append(e), then(), client.stop()))
    client.send_placement_request(name)
    run(client)
    return placements[0]


def test_a_robot_is_placed_at_home_and_an_unknown_placement_fails(rp1_server: LocalSimulator) -> None:
    client = rp1_server.client()
    Probe(client)
    home = place(client, "home")
    assert (home.valid, home.name, home.x, home.y) == (True, "home", 2.5, 2.5)
    assert home.orientation == pytest.approx(math.radians(225))
    nowhere = place(client, "nowhere")
    assert (nowhere.valid, nowhere.name) == (False, "nowhere")


def test_driving_into_a_wall_gives_range_and_contact_events_and_a_collision(rp1_server: LocalSimulator) -> None:
    client = rp1_server.client()
    probe = Probe(client)
    probe.record(rp.RangeSensorEvent, rp.ContactSensorEvent, rp.MotionStartedEvent, rp.MotionHaltedEvent)
    client.add_handler(rp.MotionHaltedEvent, lambda e: client.stop())
    place(client, "home", lambda: client.send_motion_request(rp.MotionRequest(0.5, 0.0, 20.0)))
    run(client)
    started, = probe.of(rp.MotionStartedEvent)
    halted, = probe.of(rp.MotionHaltedEvent)
    ranges = probe.of(rp.RangeSensorEvent)
    contact, = probe.of(rp.ContactSensorEvent)
    assert started.duration < 20.0, "the motion is cut short where it will hit the wall"
    assert halted.why_halted == "collision" and halted.sim_time == pytest.approx(started.duration)
    assert (contact.status, contact.object_name, contact.sim_time) == (True, "e", halted.sim_time)
    assert [r.object_name for r in ranges] == ["e"] * len(ranges) and len(ranges) >= 4
    assert [r.range for r in ranges] == sorted((r.range for r in ranges), reverse=True)
    assert all(r.status and r.range < 0.5 for r in ranges)
    assert halted.x == pytest.approx(halted.y) and 1.5 < halted.x < 1.7, "stopped at the diagonal wall"


def test_heartbeats_arrive_at_every_interval_until_cancelled(rp1_server: LocalSimulator) -> None:
    client = rp1_server.client()
    Probe(client)
    beats: List[rp.HeartbeatEvent] = []

    def beat(e: rp.HeartbeatEvent) -> None:
        beats.append(e)
        if e.sequence == 4:
            client.send_heartbeat_cancellation_request()
            client.send_timeout_request(3.0)

    client.add_handler(rp.HeartbeatEvent, beat)
    # At simulationSpeed=max simulated time passes only while a robot is on the floor.
    place(client, "home", then=lambda: client.send_heartbeat_request(0.5))
    run(client, until=5.0)
    assert [(b.sequence, b.sim_time) for b in beats] == [(1, 0.5), (2, 1.0), (3, 1.5), (4, 2.0)]


def test_the_plan_request_brings_the_white_room(rp1_server: LocalSimulator) -> None:
    client = rp1_server.client()
    plans: List[rp.PlanEvent] = []
    client.add_handler(rp.PlanEvent, lambda e: (plans.append(e), client.stop()))
    client.send_plan_request()
    run(client)
    plan = plans[0].plan
    assert plan.caption == "White Room (RP1 rev. 0.4)"
    assert [w.name for w in plan.walls] == ["a", "b", "c", "d", "e"]
    assert all(len(w.vertices) == 4 for w in plan.walls)
    goal, = plan.targets
    assert (goal.name, goal.x, goal.y, goal.radius) == ("goal", 0.4, 0.4, 0.25)
    home, = plan.placements
    assert (home.x, home.y, home.radius) == (2.5, 2.5, 0.275)
    assert home.orientation == pytest.approx(math.radians(225))


def test_encoder_and_sensor_ids_are_the_ones_the_simulator_gives_the_parts(rp1_server: LocalSimulator) -> None:
    client = rp1_server.client()
    probe = Probe(client)
    probe.record(rp.EncoderStatusEvent, rp.RangeSensorEvent)
    client.add_handler(rp.TimeoutEvent, lambda e: (
        client.send_encoder_status_request(list(probe.encoders), True), client.send_sensor_status_request(probe.sonar)))
    client.add_handler(rp.RangeSensorEvent, lambda e: probe.of(rp.EncoderStatusEvent) and client.stop(), probe.sonar)
    place(client, "home", lambda: (client.send_motion_request(rp.MotionRequest(0.1, 0.0, 1.0)),
                                   client.send_timeout_request(1.5)))
    run(client)
    left, right = probe.of(rp.EncoderStatusEvent)
    assert (left.encoder_id, right.encoder_id) == (probe.steering.left_wheel.id, probe.steering.right_wheel.id)
    assert left.request_index == right.request_index == 1 and left.clear_on_report
    assert left.accumulator == right.accumulator > 20, "both wheels turned forwards alike"
    polled = probe.of(rp.RangeSensorEvent)[-1]
    assert (polled.sensor_id, polled.sim_time, polled.status) == (probe.sonar.id, 1.5, False)


def test_two_python_robots_meeting_halt_short_of_each_other(corridor_server: LocalSimulator) -> None:
    robots = {name: corridor_server.client() for name in ("west", "east")}
    halted: Dict[str, rp.MotionHaltedEvent] = {}
    for name, client in robots.items():
        Probe(client)

        def on_halted(e: rp.MotionHaltedEvent, name: str = name, client: rp.Client = client) -> None:
            halted[name] = e
            client.stop()

        client.add_handler(rp.MotionHaltedEvent, on_halted)
        assert place(client, name).valid
    for client in robots.values():
        client.send_motion_request(rp.MotionRequest(0.3, 0.0, 20.0))
    threads = [threading.Thread(target=run, args=(client,)) for client in robots.values()]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    west, east = halted["west"], halted["east"]
    assert west.why_halted == east.why_halted == "collision"
    gap = (east.x - 0.1) - (west.x + 0.1)
    assert 0.0 < gap < 0.05, f"the robots stopped {gap:.4f} m apart"
    assert west.y == pytest.approx(0.5) and east.y == pytest.approx(0.5)


def test_the_wanderer_prints_its_position_every_second_and_exits(rp1_server: LocalSimulator) -> None:
    done = subprocess.run([sys.executable, str(EXAMPLES_DIR / "wanderer.py"), "--host", rp1_server.host,
                           "--port", str(rp1_server.port), "--duration", "12"],
                          capture_output=True, text=True, timeout=LIMIT)
    assert done.returncode == 0, done.stderr
    lines = done.stdout.splitlines()
    pattern = re.compile(r"position t=(\d+\.\d{3}) x=(-?\d+\.\d{3}) y=(-?\d+\.\d{3}) heading=(-?\d+\.\d{3})")
    matches = [pattern.fullmatch(line) for line in lines]
    assert all(matches), lines
    assert [float(m.group(1)) for m in matches] == [float(t) for t in range(1, 13)]
    positions = {(m.group(2), m.group(3)) for m in matches}
    assert len(positions) > 6, "the robot moves"
    assert all(0.0 < float(x) < 3.0 and 0.0 < float(y) < 3.0 for x, y in positions), "inside the room"


def test_the_wanderers_duration_counts_from_its_placement_on_a_clock_already_running(tmp_path) -> None:
    """A paced simulator's clock runs from its start, robots or not: a wanderer that connects late
    still wanders for the seconds it was given, not until the clock reads them."""
    properties = {"simulationSpeed": "20", "interlockEnabled": "false"}
    with LocalSimulator(REPO_ROOT / "FloorPlans" / "WhiteRoom.txt", tmp_path, repo_root=REPO_ROOT,
                        properties=properties) as server:
        time.sleep(0.5)  # some 10 simulated seconds before the robot connects
        done = subprocess.run([sys.executable, str(EXAMPLES_DIR / "wanderer.py"), "--host", server.host,
                               "--port", str(server.port), "--duration", "4"],
                              capture_output=True, text=True, timeout=LIMIT)
    assert done.returncode == 0, done.stderr
    times = [float(line.split()[1][2:]) for line in done.stdout.splitlines()]
    assert times[0] > 5.0, "the robot connected late: " + done.stdout
    assert 4 <= len(times) <= 5, "a position a second for its four seconds on the floor: " + done.stdout


def test_the_wanderer_leaving_at_a_fixed_time_gives_the_same_run_twice_and_the_server_ends(tmp_path) -> None:
    """With the interlock at max speed the robot of a client that leaves goes at the first moment the
    clock would wait for it, however fast the connection went down, so two runs give the same event
    log; and once nobody is left the server ends instead of standing still short of its time limit."""
    logs = []
    for run_number in range(2):
        workdir = tmp_path / f"run{run_number}"
        workdir.mkdir()
        properties = {"maxSimulationTime": "60", "eventLogFileName": "events.txt", "logToFile": "true",
                      "logFileName": "server.log"}
        with LocalSimulator(REPO_ROOT / "FloorPlans" / "WhiteRoom.txt", workdir, repo_root=REPO_ROOT,
                            properties=properties) as server:
            done = subprocess.run([sys.executable, str(EXAMPLES_DIR / "wanderer.py"), "--host", server.host,
                                   "--port", str(server.port), "--duration", "55"],
                                  capture_output=True, text=True, timeout=LIMIT)
            assert done.returncode == 0, done.stderr
            assert server.process.wait(LIMIT) == 0, "the server ends by itself"
        assert "No robot is left and no client is connected" in (workdir / "server.log").read_text()
        logs.append((workdir / "events.txt").read_text())
    assert logs[0] == logs[1]
    assert re.search(r"\n55\.0 \d+ Position ", logs[0]), "the wanderer's last position"


def test_clientzero_asks_for_the_plan_and_is_placed_at_home(rp1_server: LocalSimulator) -> None:
    process = subprocess.Popen([sys.executable, str(EXAMPLES_DIR / "clientzero.py"), "--host", rp1_server.host,
                                "--port", str(rp1_server.port)], stdout=subprocess.PIPE, text=True)
    try:
        lines = [process.stdout.readline().strip() for _ in range(2)]
    finally:
        process.terminate()
        process.wait(LIMIT)
    assert lines == ["floor plan 'White Room (RP1 rev. 0.4)'", 'placed at "home" (2.500, 2.500); click to move']


def _ctrl_c_as_at_a_terminal() -> None:
    """In the child: Ctrl-C's default disposition. A shell's background job starts with SIGINT ignored,
    and a Python started so never turns it into KeyboardInterrupt, which is what this test is about."""
    signal.signal(signal.SIGINT, signal.SIG_DFL)


def test_ctrl_c_ends_an_example_with_one_line_and_no_traceback(rp1_server: LocalSimulator) -> None:
    process = subprocess.Popen([sys.executable, str(EXAMPLES_DIR / "clientzero.py"), "--host", rp1_server.host,
                                "--port", str(rp1_server.port)], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                               text=True, preexec_fn=_ctrl_c_as_at_a_terminal)
    try:
        assert process.stdout.readline().startswith("floor plan"), "connected and running"
        process.send_signal(signal.SIGINT)
        _, err = process.communicate(timeout=LIMIT)
    finally:
        process.kill()
    assert "Traceback" not in err, err
    assert process.returncode in (0, 130), err


def test_an_example_with_no_simulator_says_so_in_one_line() -> None:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    done = subprocess.run([sys.executable, str(EXAMPLES_DIR / "wanderer.py"), "--host", "127.0.0.1",
                           "--port", str(port)], capture_output=True, text=True, timeout=LIMIT)
    assert done.returncode == 1
    assert done.stderr == (f"wanderer: cannot connect to the RP1 server at 127.0.0.1:{port}: "
                           "is it running? start one with rp1\n")


def test_a_refused_placement_is_reported_with_why_it_may_be(rp1_server: LocalSimulator) -> None:
    done = subprocess.run([sys.executable, str(EXAMPLES_DIR / "wanderer.py"), "--host", rp1_server.host,
                           "--port", str(rp1_server.port), "--placement", "nowhere"],
                          capture_output=True, text=True, timeout=LIMIT)
    assert done.returncode == 1
    assert "wanderer: placement 'nowhere' refused: the plan has no placement of that name" in done.stderr


def test_without_jars_the_simulator_cannot_start_and_says_how_to_build_them(monkeypatch, tmp_path) -> None:
    monkeypatch.delenv("RP1_CLASSPATH", raising=False)
    with pytest.raises(FileNotFoundError, match="run `gradle jar`"):
        LocalSimulator(REPO_ROOT / "FloorPlans" / "WhiteRoom.txt", tmp_path, repo_root=tmp_path)
