"""Our RP1 simulator as a child process, for tests and benchmarks of Python robots.

:class:`LocalSimulator` starts ``java rp1.Server`` headless on a free port with the interlock on and
``simulationSpeed=max``, so simulated time passes only as fast as the clients answer and the same
robot gives the same events on every run. It needs Java and the simulator's jars (``gradle jar`` in
the RP1 repository); the class path comes from the ``RP1_CLASSPATH`` environment variable or from
the jars under a repository given as ``repo_root``.
"""

import os
import random
import socket
import subprocess
import time
from pathlib import Path
from typing import Dict, List, Optional, Union

from .client import Client

MIN_PORT = 1
MAX_PORT = 65535


def find_classpath(repo_root: Union[str, Path, None] = None) -> str:
    """``RP1_CLASSPATH`` if set, else the jars under ``repo_root``'s rp1-server and rp1-rossum.

    Raises:
        FileNotFoundError: saying to run ``gradle jar`` when neither exists.
    """
    from_env = os.environ.get("RP1_CLASSPATH")
    if from_env:
        return from_env
    jars: List[str] = []
    if repo_root is not None:
        for module in ("rp1-server", "rp1-rossum"):
            jars += sorted(str(p) for p in (Path(repo_root) / module / "build" / "libs").glob("*.jar"))
    if not jars:
        raise FileNotFoundError("the simulator's jars are missing: run `gradle jar` in the RP1 repository "
                                "(or set RP1_CLASSPATH to the class path of rp1-server and rp1-rossum)")
    return os.pathsep.join(jars)


def free_port() -> int:
    """A port free now within the range the simulator accepts (every TCP port). Port 0 is tried first;
    random ports come next."""
    rng = random.Random()
    for attempt in range(1000):
        candidate = 0 if attempt == 0 else rng.randint(MIN_PORT, MAX_PORT)
        with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
            try:
                s.bind(("127.0.0.1", candidate))
            except OSError:
                continue
            port = s.getsockname()[1]
        if MIN_PORT <= port <= MAX_PORT:
            return port
    raise RuntimeError(f"no free port found in {MIN_PORT}..{MAX_PORT}")


class LocalSimulator:
    """A headless simulator on ``plan`` (a floor-plan file), started at once; stop it with
    :meth:`stop` or use it as a context manager. ``properties`` add or override server keys
    (docs/properties.md); the server's output goes to ``server-output.txt`` in ``workdir``.

    Raises:
        FileNotFoundError: if there are no jars (see :func:`find_classpath`).
        RuntimeError: if the simulator exits or does not listen within ``start_timeout`` seconds.
    """

    def __init__(self, plan: Union[str, Path], workdir: Union[str, Path], *, classpath: Optional[str] = None,
                 repo_root: Union[str, Path, None] = None, properties: Optional[Dict[str, str]] = None,
                 start_timeout: float = 30.0) -> None:
        self.host = "127.0.0.1"
        self.port = free_port()
        self.plan = Path(plan).resolve()
        workdir = Path(workdir)
        settings = {"port": str(self.port), "enableGUI": "false", "simulationSpeed": "max",
                    "interlockEnabled": "true", "floorPlanFileName": str(self.plan), "logToSystemOut": "false",
                    "randomSeed": "1", **(properties or {})}
        props = workdir / "server.ini"
        props.write_text("".join(f"{k}={v}\n" for k, v in settings.items()), encoding="utf-8")
        self.output = workdir / "server-output.txt"
        command = ["java", "-Djava.awt.headless=true", "-cp", classpath or find_classpath(repo_root),
                   "rp1.Server", "-p", str(props)]
        with open(self.output, "wb") as out:
            self.process = subprocess.Popen(command, cwd=workdir, stdin=subprocess.DEVNULL, stdout=out,
                                            stderr=subprocess.STDOUT)
        self.clients: List[Client] = []
        try:
            self._wait_until_listening(start_timeout)
        except BaseException:
            self.stop()
            raise

    def _wait_until_listening(self, timeout: float) -> None:
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if self.process.poll() is not None:
                raise RuntimeError(f"the simulator exited with status {self.process.returncode}:\n"
                                   f"{self.output.read_text(errors='replace')}")
            try:
                socket.create_connection((self.host, self.port), timeout=1.0).close()
                return
            except OSError:
                time.sleep(0.05)
        raise RuntimeError(f"the simulator did not listen on port {self.port} within {timeout} s")

    def client(self) -> Client:
        """A client connected to this simulator, closed by :meth:`stop`."""
        client = Client(self.host, self.port).connect(timeout=10.0)
        self.clients.append(client)
        return client

    def stop(self, timeout: float = 5.0) -> None:
        """Closes the clients, then ends the simulator (killing it if it does not stop in time)."""
        for client in self.clients:
            client.close()
        if self.process.poll() is None:
            self.process.terminate()
            try:
                self.process.wait(timeout)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait()

    def __enter__(self) -> "LocalSimulator":
        return self

    def __exit__(self, *exc_info: object) -> None:
        self.stop()
