"""Fixtures that start our simulator from the built jars (see rp1client.simulator).

Headless, on a free port, with the interlock on and ``simulationSpeed=max``. The class path comes
from ``RP1_CLASSPATH`` (the Gradle task sets it) or from the jars under ``rp1-server/build/libs`` and
``rp1-rossum/build/libs``; without either the tests fail and say to run ``gradle jar``.
"""

from pathlib import Path
from typing import Iterator

import pytest

from rp1client.simulator import LocalSimulator
from support import REPO_ROOT

CORRIDOR = """units: meters;
caption: "Corridor";
wall bottom { geometry: 0, 0, 4, 0, 0.05; }
wall right  { geometry: 4, 0, 4, 1, 0.05; }
wall top    { geometry: 4, 1, 0, 1, 0.05; }
wall left   { geometry: 0, 1, 0, 0, 0.05; }
placement west { geometry: 1.0, 0.5, 0, 0.2; }
placement east { geometry: 3.0, 0.5, 180, 0.2; }
"""


def start(plan: Path, workdir: Path) -> LocalSimulator:
    try:
        return LocalSimulator(plan, workdir, repo_root=REPO_ROOT)
    except (FileNotFoundError, RuntimeError) as e:
        pytest.fail(str(e), pytrace=False)


@pytest.fixture
def rp1_server(tmp_path: Path) -> Iterator[LocalSimulator]:
    """Our simulator on the White Room (3 m x 3 m, placement "home" at (2.5, 2.5) facing 225 degrees)."""
    with start(REPO_ROOT / "FloorPlans" / "WhiteRoom.txt", tmp_path) as server:
        yield server


@pytest.fixture
def corridor_server(tmp_path: Path) -> Iterator[LocalSimulator]:
    """Our simulator on a 4 m x 1 m corridor with placements "west" and "east" facing each other."""
    plan = tmp_path / "corridor.txt"
    plan.write_text(CORRIDOR)
    with start(plan, tmp_path) as server:
        yield server
