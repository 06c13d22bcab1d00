"""How long ``assur classify`` of a fixture takes as a whole process, next to ``python -c pass``.

Each round runs, in turn, a bare interpreter (``python -c pass``) and the
command line on one bundled fixture (``python -m kinematics classify FILE``,
and the installed ``assur`` script when it sits beside the interpreter), every
process started fresh, output discarded. The times are medians over the
rounds, so the noise of a shared machine falls on all alike; the ratio
``classify / pass`` is what issue 12 bounds (goal: at most 6x).

Bytecode is cached as on any installed copy (pip compiles it at install):
this machine sets ``PYTHONDONTWRITEBYTECODE``, which would make every run
compile assur's modules from source again (about 80 ms), so the children run
without it and keep their bytecode under a temporary ``PYTHONPYCACHEPREFIX``
(the checkout is left untouched); the warm-up run fills it.

``--imports`` also prints the slowest imports of one classify run (from
``python -X importtime``), the place to look when the ratio grows.

Usage::

    python benchmarks/startup.py [--rounds 15] [--fixture fixtures/fourbar.edges] [--imports]
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
GOAL = 6.0  # classify of a fixture / python -c pass, whole process, at most


def _environment(cache: str) -> dict[str, str]:
    """This process's environment with bytecode written, under ``cache``."""
    environment = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    environment["PYTHONPYCACHEPREFIX"] = cache
    return environment


def _run(command: list[str], environment: dict[str, str]) -> float:
    start = time.perf_counter()
    subprocess.run(
        command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True, env=environment
    )
    return time.perf_counter() - start


def _commands(fixture: str) -> dict[str, list[str]]:
    commands = {
        "python -c pass": [sys.executable, "-c", "pass"],
        "python -m kinematics classify": [sys.executable, "-m", "kinematics", "classify", fixture],
    }
    script = Path(sys.executable).parent / "assur"
    if script.is_file():
        commands["assur classify"] = [str(script), "classify", fixture]
    return commands


def measure(fixture: str, rounds: int, environment: dict[str, str]) -> dict[str, float]:
    """Median wall time of each command over ``rounds`` interleaved rounds (one warm-up)."""
    commands = _commands(fixture)
    for command in commands.values():
        _run(command, environment)
    times: dict[str, list[float]] = {name: [] for name in commands}
    for _ in range(rounds):
        for name, command in commands.items():
            times[name].append(_run(command, environment))
    return {name: statistics.median(values) for name, values in times.items()}


def slowest_imports(
    fixture: str, environment: dict[str, str], top: int = 15
) -> list[tuple[int, str]]:
    """The ``top`` largest cumulative import times (µs) of one classify run."""
    command = [sys.executable, "-X", "importtime", "-m", "kinematics", "classify", fixture]
    done = subprocess.run(command, capture_output=True, text=True, check=True, env=environment)
    rows = []
    for line in done.stderr.splitlines():
        parts = line.split("|")
        if len(parts) == 3 and parts[1].strip().isdigit():
            rows.append((int(parts[1]), parts[2].rstrip()))
    return sorted(rows, reverse=True)[:top]


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=15)
    parser.add_argument("--fixture", default=str(ROOT / "fixtures" / "fourbar.edges"))
    parser.add_argument("--imports", action="store_true", help="print the slowest imports")
    args = parser.parse_args(argv)
    os.chdir(ROOT)
    print(f"load average before: {' '.join(f'{x:.2f}' for x in os.getloadavg())}")
    with tempfile.TemporaryDirectory(prefix="assur-pycache-") as cache:
        environment = _environment(cache)
        medians = measure(args.fixture, args.rounds, environment)
        imports = slowest_imports(args.fixture, environment) if args.imports else []
    if imports:
        print("slowest imports of one classify run (cumulative µs):")
        for micros, name in imports:
            print(f"  {micros:8d}  {name}")
    base = medians["python -c pass"]
    for name, seconds in medians.items():
        print(f"{name:32s} {seconds * 1e3:7.1f} ms  {seconds / base:5.2f}x")
    print(f"load average after: {' '.join(f'{x:.2f}' for x in os.getloadavg())}")
    worst = max(seconds / base for name, seconds in medians.items() if name != "python -c pass")
    verdict = "met" if worst <= GOAL else "NOT met"
    print(f"classify / python -c pass: {worst:.2f}x (goal <= {GOAL:g}x): {verdict}")
    return 0 if worst <= GOAL else 2


if __name__ == "__main__":
    sys.exit(main())
