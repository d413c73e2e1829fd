#!/usr/bin/env bash
# Installs mdbook, the tool that builds the user guide (docs/), into the
# project's own tool folder target/tools/bin, unless one is already on PATH
# or there. Prints the path of the mdbook to use on its last line, or
# "skipped: <reason>" and exits 0 where it cannot install (no network, no
# cargo), so that CI says what it skipped instead of failing.
set -uo pipefail
cd "$(dirname "$0")/.."
root="$PWD/target/tools"
if command -v mdbook >/dev/null 2>&1; then
    command -v mdbook
    exit 0
fi
if [ -x "$root/bin/mdbook" ]; then
    echo "$root/bin/mdbook"
    exit 0
fi
if ! command -v cargo >/dev/null 2>&1; then
    echo "skipped: no cargo to install mdbook with"
    exit 0
fi
if ! cargo install mdbook --locked --root "$root" >&2; then
    echo "skipped: cargo install mdbook --locked failed (offline?)"
    exit 0
fi
echo "$root/bin/mdbook"
