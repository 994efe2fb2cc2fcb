"""The run a sweep gives a robot: parameters, seed and results (rp1client.run), and a whole sweep
whose robot is a Python program (``--client``)."""

import csv
import subprocess
import sys
from pathlib import Path

import pytest

import rp1client as rp
from rp1client.simulator import find_classpath
from support import REPO_ROOT


def test_parameters_seed_and_results_come_from_the_environment_a_sweep_sets(tmp_path: Path) -> None:
    results = tmp_path / "results.txt"
    env = {"RP1_SEED": "17", "RP1_PARAM_max_speed": "0.5", "RP1_RESULTS": str(results)}
    assert rp.run_parameter("max.speed", env) == "0.5"
    assert rp.run_parameter("turn", env) is None
    assert rp.run_seed(env) == 17
    rp.report_run_result("score", 2.5, env)
    rp.report_run_result("score", 3, env)
    assert results.read_text().splitlines() == ["score 2.5", "score 3.0"]


def test_outside_a_sweep_there_are_no_parameters_seed_zero_and_results_go_nowhere() -> None:
    assert rp.run_parameter("speed", {}) is None
    assert rp.run_seed({}) == 0
    rp.report_run_result("score", 1.0, {})


def test_bad_results_are_refused_naming_the_argument() -> None:
    with pytest.raises(ValueError, match="name must be letters"):
        rp.report_run_result("two words", 1.0, {})
    with pytest.raises(ValueError, match="value of score must be a finite number"):
        rp.report_run_result("score", float("nan"), {})


def test_a_sweep_runs_a_python_robot_per_run_with_its_parameters_seed_and_results(tmp_path: Path) -> None:
    plan = tmp_path / "open.txt"
    plan.write_text('caption: "open";\nwall w { geometry: 0, 0, 6, 0, 0.05; }\n'
                    "placement home { geometry: 1, 1, 0, 0.2; }\n")
    props = tmp_path / "python.ini"
    props.write_text(f"floorPlanFileName={plan}\nenableGUI=false\ninterlockEnabled=true\nsimulationSpeed=max\n"
                     "maxSimulationTime=30\n")
    robot = REPO_ROOT / "rp1-python" / "examples" / "sweep_robot.py"
    done = subprocess.run(["java", "-Djava.awt.headless=true", "-cp", find_classpath(REPO_ROOT), "rp1.Sweep",
                           "-p", str(props), "--seeds", "5-6", "--vary", "param.speed=0.1,0.3", "--jobs", "2",
                           "--client", f"{sys.executable} {robot}", "--out", str(tmp_path / "out")],
                          cwd=tmp_path, capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stdout + done.stderr
    with open(tmp_path / "out" / "results.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    assert [(r["param.speed"], r["seed"]) for r in rows] == [("0.1", "5"), ("0.1", "6"), ("0.3", "5"), ("0.3", "6")]
    for r in rows:
        assert r["robot"] == "Straight"
        assert r["result.speed"] == r["param.speed"]
        assert r["result.seed"] == r["seed"]
        assert float(r["distance"]) == pytest.approx(2 * float(r["param.speed"]))
        assert r["reason"] == "nobody-left"
        assert r["status"] == "0"
