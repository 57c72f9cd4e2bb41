"""The lanes' check fails a fast-lane test that starts a server or a process, and lets a marked one."""

from __future__ import annotations

import re

import pytest

from tests.lanes import _starts_the_browser

pytest_plugins = ["pytester"]

SERVER = """
import socket
import pytest

def _listen():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        s.listen()

def test_unmarked_server():
    _listen()

@pytest.mark.slow
def test_slow_server():
    _listen()

@pytest.mark.browser
def test_browser_server():
    _listen()

@pytest.fixture
def served():
    _listen()

def test_unmarked_fixture_server(served):
    pass
"""


def test_a_server_in_the_fast_lane_fails_and_a_marked_one_passes(pytester: pytest.Pytester) -> None:
    pytester.makeini("[pytest]\nmarkers =\n    slow: s\n    browser: b\n")
    pytester.makepyfile(test_inner=SERVER)
    result = pytester.runpytest_inprocess("-p", "tests.lanes", "--strict-markers", "-rf")
    result.assert_outcomes(passed=2, failed=2)  # a fixture's server fails the test that asked for it
    result.stdout.fnmatch_lines(["*the fast lane starts no process and no server*", "*listened on*mark the test slow*"])
    failed = set(re.findall(r"^FAILED test_inner.py::(\w+)", result.stdout.str(), re.M))
    assert failed == {"test_unmarked_server", "test_unmarked_fixture_server"}


def test_the_browser_is_told_from_other_processes() -> None:
    node = "/venv/lib/python3.11/site-packages/playwright/driver/node"
    assert _starts_the_browser(
        [node, "/venv/lib/python3.11/site-packages/playwright/driver/package/cli.js", "run-driver"]
    )
    assert _starts_the_browser(["/usr/bin/chromium", "--headless"])
    assert not _starts_the_browser(["/venv/bin/python", "-m", "rigidrel_app.cli"])
    assert not _starts_the_browser("ls")
