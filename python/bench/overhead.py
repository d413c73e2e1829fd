"""The cost of calling from Python: 10,000 calls of
``pounding.run(preset="set1", method="exact")`` (peaks only) against the
same 10,000 runs inside Rust, each building the same typed report
(``pounding._native._run_in_rust``). The difference per call is the
binding's overhead: keywords to arguments through the command line's
parser, releasing and taking back the GIL, and the report as Python objects.
Times are the calling thread's CPU time (``time.thread_time``: the run
happens on that thread), best of five interleaved rounds, so that other
work on a shared machine weighs little.

    python python/bench/overhead.py [CALLS]

For reference it also prints the command line's own median of one solve,
``pounding run --preset set1 --method exact --repeat N`` (a report is two
solves: the run, and the run without contact for the minimum gap), when
the release binary is found.
"""

import json
import os
import pathlib
import subprocess
import sys
import time

import pounding
from pounding import _native

CALLS = int(sys.argv[1]) if len(sys.argv) > 1 else 10_000
ROUNDS = 5
CASE = {"preset": "set1", "method": "exact"}


def python_calls(n: int) -> float:
    start = time.thread_time()
    for _ in range(n):
        pounding.run(**CASE)
    return time.thread_time() - start


def rust_runs(n: int) -> float:
    start = time.thread_time()
    _native._run_in_rust(n, **CASE)
    return time.thread_time() - start


def parse_and_call(n: int) -> float:
    """One run inside Rust per call: the keywords parsed, the GIL released."""
    start = time.thread_time()
    for _ in range(n):
        _native._run_in_rust(1, **CASE)
    return time.thread_time() - start


report = json.dumps(pounding.run(**CASE))


def json_loads(n: int) -> float:
    """For scale: Python's own JSON reader making the same objects."""
    start = time.thread_time()
    for _ in range(n):
        json.loads(report)
    return time.thread_time() - start


python_calls(CALLS // 10)  # warm-up
# Interleaved rounds, so that a busy machine weighs on all alike.
py, rs, pc = [], [], []
for _ in range(ROUNDS):
    py.append(python_calls(CALLS))
    rs.append(rust_runs(CALLS))
    pc.append(parse_and_call(CALLS))
py_us, rs_us, pc_us = (min(t) / CALLS * 1e6 for t in (py, rs, pc))
loads_us = min(json_loads(CALLS) for _ in range(ROUNDS)) / CALLS * 1e6
print(f"{CALLS} calls, best of {ROUNDS} rounds, CPU time of the calling thread:")
print(f"  pounding.run from Python  {py_us:8.2f} µs per call")
print(f"  the same inside Rust      {rs_us:8.2f} µs per run")
print(f"  overhead                  {py_us - rs_us:8.2f} µs per call, of which")
print(f"    keywords to arguments and the call   {pc_us - rs_us:6.2f} µs")
print(f"    the report as Python objects         {py_us - pc_us:6.2f} µs")
print(f"  (json.loads of the same report: {loads_us:.2f} µs)")

repo = pathlib.Path(__file__).resolve().parents[2]
binary = pathlib.Path(os.environ.get("POUNDING_BIN", repo / "target" / "release" / "pounding"))
if binary.exists():
    out = subprocess.run(
        [str(binary), "run", "--preset", "set1", "--method", "exact", "--repeat", str(CALLS), "--format", "json"],
        capture_output=True,
        text=True,
        check=True,
    )
    solve_us = json.loads(out.stdout)["elapsed_ms"] * 1e3
    print(f"  (pounding run --repeat {CALLS}: median solve {solve_us:.2f} µs)")
