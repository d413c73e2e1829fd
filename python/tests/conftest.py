"""The command line's binary, against which the module is checked."""

import json
import os
import pathlib
import subprocess

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]


def binary() -> pathlib.Path:
    """`POUNDING_BIN`, else the release binary in cargo's target directory."""
    if os.environ.get("POUNDING_BIN"):
        return pathlib.Path(os.environ["POUNDING_BIN"])
    target = pathlib.Path(os.environ.get("CARGO_TARGET_DIR", REPO / "target"))
    return target / "release" / "pounding"


class Cli:
    def __init__(self, path: pathlib.Path):
        self.path = path

    def __call__(self, *args: str) -> subprocess.CompletedProcess:
        return subprocess.run(
            [str(self.path), *args], capture_output=True, text=True, timeout=600
        )

    def json(self, *args: str) -> dict:
        out = self(*args, "--format", "json")
        assert out.returncode == 0, out.stderr
        return json.loads(out.stdout)

    def error(self, *args: str) -> str:
        """The one-line message of a bad input (exit code 2), without `error: `."""
        out = self(*args)
        assert out.returncode == 2, (out.returncode, out.stderr)
        line = out.stderr.strip().splitlines()[-1]
        assert line.startswith("error: "), line
        return line[len("error: ") :]


@pytest.fixture(scope="session")
def cli() -> Cli:
    path = binary()
    if not path.exists():
        pytest.fail(f"{path}: build it first (cargo build --release), or set POUNDING_BIN")
    return Cli(path)
