"""The ``rp1_server`` fixture: our simulator, started from the built jars as a child process.

Headless, on a free port, with the interlock on and ``simulationSpeed=max``, so simulated time
passes only as fast as the test's clients answer. The class path comes from ``RP1_CLASSPATH`` (the
Gradle task sets it) or from the jars under ``rp1-server/build/libs`` and ``rp1-rossum/build/libs``.
"""

import os
import random
import socket
import subprocess
import time
from pathlib import Path
from typing import Iterator, List

import pytest

import rp1client as rp
from support import REPO_ROOT

START_TIMEOUT = 30.0
STOP_TIMEOUT = 5.0


def server_classpath() -> str:
    """The simulator's class path, or a test failure saying how to build it."""
    from_env = os.environ.get("RP1_CLASSPATH")
    if from_env:
        return from_env
    jars = sorted(str(p) for module in ("rp1-server", "rp1-rossum")
                  for p in (REPO_ROOT / module / "build" / "libs").glob("*.jar"))
    if not jars:
        pytest.fail("the simulator's jars are missing: run `gradle jar` in the repository root "
                    "(or set RP1_CLASSPATH)", pytrace=False)
    return os.pathsep.join(jars)


def free_port() -> int:
    """A port that is free now, within the 1025..32767 the server accepts (this machine's ephemeral
    ports may all lie above it, so port 0 is tried first, then random ports in the range)."""
    rng = random.Random()
    for attempt in range(1000):
        candidate = 0 if attempt == 0 else rng.randint(1025, 32767)
        with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
            try:
                s.bind(("127.0.0.1", candidate))
            except OSError:
                continue
            port = s.getsockname()[1]
        if 1025 <= port <= 32767:
            return port
    raise RuntimeError("no free port found in 1025..32767")


class RunningServer:
    """A simulator process and the clients the test opened on it."""

    def __init__(self, plan: Path, workdir: Path, extra: str = "") -> None:
        self.host = "127.0.0.1"
        self.port = free_port()
        self.plan = plan
        props = workdir / "server.ini"
        props.write_text(f"port={self.port}\nenableGUI=false\nsimulationSpeed=max\ninterlockEnabled=true\n"
                         f"floorPlanFileName={plan.resolve()}\nlogToSystemOut=false\nrandomSeed=1\n{extra}")
        self.output = workdir / "server-output.txt"
        with open(self.output, "wb") as out:
            self.process = subprocess.Popen(
                ["java", "-Djava.awt.headless=true", "-cp", server_classpath(), "rp1.Server", "-p", str(props)],
                cwd=workdir, stdin=subprocess.DEVNULL, stdout=out, stderr=subprocess.STDOUT)
        self.clients: List[rp.Client] = []
        self._wait_until_listening()

    def _wait_until_listening(self) -> None:
        deadline = time.monotonic() + START_TIMEOUT
        while time.monotonic() < deadline:
            if self.process.poll() is not None:
                pytest.fail(f"the simulator exited with status {self.process.returncode}:\n{self.output.read_text()}",
                            pytrace=False)
            try:
                socket.create_connection((self.host, self.port), timeout=1.0).close()
                return
            except OSError:
                time.sleep(0.1)
        self.stop()
        pytest.fail(f"the simulator did not listen on port {self.port} within {START_TIMEOUT} s", pytrace=False)

    def client(self) -> rp.Client:
        """A connected client, closed when the test ends."""
        client = rp.Client(self.host, self.port).connect(timeout=10.0)
        self.clients.append(client)
        return client

    def stop(self) -> None:
        for client in self.clients:
            client.close()
        self.process.terminate()
        try:
            self.process.wait(STOP_TIMEOUT)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()


@pytest.fixture
def rp1_server(tmp_path: Path) -> Iterator[RunningServer]:
    """Our simulator on the White Room (3 m x 3 m, placement "home" at (2.5, 2.5) facing 225 degrees)."""
    server = RunningServer(REPO_ROOT / "FloorPlans" / "WhiteRoom.txt", tmp_path)
    yield server
    server.stop()


@pytest.fixture
def corridor_server(tmp_path: Path) -> Iterator[RunningServer]:
    """Our simulator on a 4 m x 1 m corridor with placements "west" and "east" facing each other."""
    plan = tmp_path / "corridor.txt"
    plan.write_text(
        'units: meters;\ncaption: "Corridor";\n'
        "wall bottom { geometry: 0, 0, 4, 0, 0.05; }\nwall right { geometry: 4, 0, 4, 1, 0.05; }\n"
        "wall top { geometry: 4, 1, 0, 1, 0.05; }\nwall left { geometry: 0, 1, 0, 0, 0.05; }\n"
        "placement west { geometry: 1.0, 0.5, 0, 0.2; }\nplacement east { geometry: 3.0, 0.5, 180, 0.2; }\n")
    server = RunningServer(plan, tmp_path)
    yield server
    server.stop()

