"""The run a robot is part of when a sweep starts it (``rp1 sweep ... --client 'python3 robot.py'``).

The sweep starts the program once per run with the run in its environment (the same names the Java
library reads, docs/guide.md "Experiments"):

``RP1_HOST``, ``RP1_PORT``
    where the run's server listens (:class:`rp1client.Client` uses them when given no address);
``RP1_SEED``
    the run's seed, so the robot's own randomness is reproducible;
``RP1_PARAM_NAME``
    the run's parameter ``param.NAME`` (characters of NAME other than letters, digits and ``_``
    written as ``_``);
``RP1_RESULTS``
    a file to which results of the robot's own are appended, a line ``NAME VALUE`` each; the sweep
    takes the last value of each name into the ``result.NAME`` column of results.csv.

Outside a sweep there are no parameters, the seed is 0 and results go nowhere.
"""

import math
import os
import re
from typing import Mapping, Optional

PORT_VARIABLE = "RP1_PORT"
HOST_VARIABLE = "RP1_HOST"
SEED_VARIABLE = "RP1_SEED"
PARAMETER_PREFIX = "RP1_PARAM_"
RESULTS_VARIABLE = "RP1_RESULTS"

_NAME = re.compile(r"[A-Za-z0-9_.-]+")


def parameter_variable(name: str) -> str:
    """The environment variable holding parameter ``name``: ``RP1_PARAM_`` and the name with every
    character other than a letter, a digit or ``_`` replaced by ``_``."""
    return PARAMETER_PREFIX + re.sub(r"[^A-Za-z0-9_]", "_", name)


def run_parameter(name: str, environ: Optional[Mapping[str, str]] = None) -> Optional[str]:
    """The value of the run's parameter ``name`` (``param.NAME`` of the sweep), or None."""
    env = os.environ if environ is None else environ
    return env.get(parameter_variable(name))


def run_seed(environ: Optional[Mapping[str, str]] = None) -> int:
    """The run's seed, or 0 outside a sweep.

    Raises:
        ValueError: if ``RP1_SEED`` is not a whole number.
    """
    env = os.environ if environ is None else environ
    value = env.get(SEED_VARIABLE)
    if value is None:
        return 0
    try:
        return int(value.strip())
    except ValueError:
        raise ValueError(f"{SEED_VARIABLE}={value}: not a seed") from None


def report_run_result(name: str, value: float, environ: Optional[Mapping[str, str]] = None) -> None:
    """Reports a result of the robot's own; the last value reported for a name wins.

    Raises:
        ValueError: naming the argument if ``name`` is not letters, digits, ``_``, ``.`` or ``-``,
            or ``value`` is not a finite number.
    """
    if not isinstance(name, str) or not _NAME.fullmatch(name):
        raise ValueError(f"report_run_result: name must be letters, digits, _, . or -, got {name!r}")
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise ValueError(f"report_run_result: value of {name} must be a finite number, got {value!r}")
    env = os.environ if environ is None else environ
    path = env.get(RESULTS_VARIABLE)
    if path is None:
        return
    with open(path, "a", encoding="utf-8") as f:
        f.write(f"{name} {float(value)!r}\n")
