#!/usr/bin/env bash
# The Python module as a fresh machine installs it: a new virtual
# environment, the build backend and test runner pinned in
# python/requirements-test.txt, `pip install ./python`, then pytest against
# the release binary that `cargo test --release` (or `cargo build
# --release`) left in cargo's target directory. Without Python ≥ 3.9 and
# its venv module, it says so and passes.
set -euo pipefail
cd "$(dirname "$0")/.."
python=${PYTHON:-python3}
if ! command -v "$python" >/dev/null 2>&1; then
    echo "skipped: the Python module's tests: no $python on PATH"
    exit 0
fi
if ! "$python" -c 'import sys; sys.exit(sys.version_info < (3, 9))'; then
    echo "skipped: the Python module's tests: $("$python" --version 2>&1) is older than 3.9"
    exit 0
fi
if ! "$python" -c 'import venv, ensurepip' >/dev/null 2>&1; then
    echo "skipped: the Python module's tests: $python has no venv/ensurepip (Debian: apt-get install python3-venv)"
    exit 0
fi
target=${CARGO_TARGET_DIR:-target}
mkdir -p "$target"
venv="$(cd "$target" && pwd)/python-venv"
start=$SECONDS
"$python" -m venv --clear "$venv"
"$venv/bin/python" -m pip install --quiet --disable-pip-version-check -r python/requirements-test.txt
# maturin comes from the venv; the wheel's Rust builds in cargo's target
# directory beside the library's own build, and with the repository's
# .cargo/config.toml, so its floats are the command line's bit for bit.
PATH="$venv/bin:$PATH" "$venv/bin/python" -m pip install --quiet --disable-pip-version-check \
    --no-build-isolation ./python
test -x "$target/release/pounding" || cargo build --release --bin pounding
POUNDING_BIN="$target/release/pounding" "$venv/bin/python" -m pytest -q python/tests
echo "the Python module's install and tests: $((SECONDS - start)) s"
