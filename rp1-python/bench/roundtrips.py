#!/usr/bin/env python3
"""Interlocked round trips per second of a Python client over loopback TCP.

A round trip is what the Java bench's RoundTripClient measures: the client asks for a zero-length
timeout, receives the timeout event (interlock on, simulationSpeed=max), its handler asks for the
next one, and the library acknowledges the event. Five one-second windows are measured against our
simulator started from the built jars; the best and the median are printed, with the client's CPU
time per round trip (what the Python side costs).

    python bench/roundtrips.py          (or: gradle pythonBench)
"""

import statistics
import sys
import tempfile
import threading
import time
from pathlib import Path
from typing import List, Tuple

import rp1client as rp
from rp1client.simulator import LocalSimulator

REPO_ROOT = Path(__file__).resolve().parents[2]
WINDOWS = 5
WINDOW_SECONDS = 1.0


class RoundTrips:
    """The client side: each timeout's handler asks for the next while a window is open."""

    def __init__(self, client: rp.Client) -> None:
        self.client = client
        self.count = 0
        self.running = False
        body = rp.Body("round trip")
        body.add_part(rp.Circle(0.0, 0.0, 0.05))
        client.send_body_specification(body)
        client.add_handler(rp.TimeoutEvent, self.on_timeout)

    def on_timeout(self, event: rp.TimeoutEvent) -> None:
        self.count += 1
        if self.running:
            self.client.send_timeout_request(0.0)

    def measure(self, seconds: float) -> Tuple[float, float]:
        """Round trips per second over one window, and the process CPU seconds per round trip."""
        n0, t0, cpu0 = self.count, time.perf_counter(), time.process_time()
        self.running = True
        self.client.send_timeout_request(0.0)
        time.sleep(seconds)
        n1, t1, cpu1 = self.count, time.perf_counter(), time.process_time()
        self.running = False
        time.sleep(0.05)
        return (n1 - n0) / (t1 - t0), (cpu1 - cpu0) / max(1, n1 - n0)


def main() -> int:
    with tempfile.TemporaryDirectory(prefix="rp1-bench-") as workdir, \
            LocalSimulator(REPO_ROOT / "FloorPlans" / "WhiteRoom.txt", workdir, repo_root=REPO_ROOT) as server:
        client = server.client()
        bench = RoundTrips(client)
        loop = threading.Thread(target=client.run, daemon=True)
        loop.start()
        bench.measure(0.5)
        windows: List[Tuple[float, float]] = [bench.measure(WINDOW_SECONDS) for _ in range(WINDOWS)]
        client.close()
        loop.join(5.0)
    rates = [rate for rate, _ in windows]
    cpu = statistics.median(c for _, c in windows)
    print(f"Python {sys.version.split()[0]} client, loopback TCP, interlocked round trips: "
          f"{max(rates):,.0f}/s best, {statistics.median(rates):,.0f}/s median "
          f"(windows: {', '.join(f'{r:,.0f}' for r in rates)}); client CPU {cpu * 1e6:.0f} us per round trip")
    return 0


if __name__ == "__main__":
    sys.exit(main())
