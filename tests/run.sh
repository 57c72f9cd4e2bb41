#!/usr/bin/env bash
# Install everything the suite needs on a fresh machine, then run all of it:
# ruff, pyright, the import contract, and pytest (core, CLI, browser tests).
set -euo pipefail
cd "$(dirname "$0")/.."

if ! [ -x /usr/bin/chromium ]; then
    echo "installing Debian's chromium for the browser tests" >&2
    SUDO=""; [ "$(id -u)" = 0 ] || SUDO="sudo"
    $SUDO apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq chromium >/dev/null
fi

python3 -m venv .venv
.venv/bin/python -m pip install -q --disable-pip-version-check -e '.[test]'

.venv/bin/ruff check .
.venv/bin/ruff format --check .
.venv/bin/pyright
.venv/bin/lint-imports
# every lane: the fast one (plain `pytest`), slow and browser, on every core (pyproject's addopts:
# `-n auto --dist loadfile`, a worker takes a whole test file, so a file's shared tab or server is
# opened once); then the tests that compare rates measured in their own process, in one process
# with nothing running beside them
# (pytest's status 5 is "nothing selected", as for a `-k` that picks tests of one part only)
lane() { .venv/bin/python -m pytest -q "$@" || { status=$?; [ "$status" = 5 ] || exit "$status"; }; }
lane -m "not alone" "$@"
lane -m "alone" -n 0 "$@"
