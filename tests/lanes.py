"""The suite's lanes, and the check that keeps every test in the right one (a pytest plugin).

Plain ``pytest`` runs the fast lane: ``addopts`` in ``pyproject.toml`` deselects the tests marked
``slow`` (a server, a subprocess, a Jupyter kernel, an export that renders through Chromium, or
seconds of work) and ``browser`` (Debian's chromium driven by playwright). ``bash tests/run.sh``,
the README's test command, runs every lane: all but the ``alone`` tests on two workers
(pytest-xdist), then the ``alone`` ones (rates compared with a baseline measured in the same
process) with nothing beside them.

A test in the fast lane that starts a process or listens on a socket fails, naming what it started:
every ``subprocess.Popen``, ``os.system``, ``os.fork``, ``os.posix_spawn`` and
``multiprocessing`` start, and every ``socket.listen``, is checked against the marks of the test
running at that moment (its setup, call and teardown, fixtures included). Starting playwright's
driver (which starts Chromium) needs the ``browser`` mark itself; anything else needs ``slow`` or
``browser``.
"""

from __future__ import annotations

import multiprocessing.process
import os
import socket
import subprocess
from collections.abc import Callable, Generator
from typing import Any

import pytest

SLOW, BROWSER = "slow", "browser"

_running: list[pytest.Item] = []  # the test whose setup, call or teardown is running (at most one)
_offences: dict[str, list[str]] = {}  # test id -> what it started without the mark that allows it


def _lanes(item: pytest.Item) -> set[str]:
    return {m.name for m in item.iter_markers()} & {SLOW, BROWSER}


def _starts_the_browser(args: object) -> bool:
    """Playwright's driver (``node .../playwright/driver/...``) or a Chromium binary."""
    words = [str(a) for a in args] if isinstance(args, list | tuple) else [str(args)]
    return any("playwright" in w and "driver" in w for w in words) or any(
        os.path.basename(w) in {"chromium", "chrome", "headless_shell"} for w in words[:1]
    )


def _check(what: str, *, browser: bool = False) -> None:
    """Record ``what`` against the running test if its marks do not allow it."""
    if not _running:
        return  # collection, or a session fixture between tests: no test to blame
    item = _running[-1]
    lanes = _lanes(item)
    needed = {BROWSER} if browser else {SLOW, BROWSER}
    if not lanes & needed:
        mark = "browser" if browser else "slow (or browser)"
        _offences.setdefault(item.nodeid, []).append(f"{what}: mark the test {mark}")


def _guarded(original: Callable[..., Any], describe: Callable[..., tuple[str, bool]]) -> Callable[..., Any]:
    def guarded(*args: Any, **kwargs: Any) -> Any:
        what, browser = describe(*args, **kwargs)
        _check(what, browser=browser)
        return original(*args, **kwargs)

    guarded.__wrapped__ = original  # type: ignore[attr-defined]
    return guarded


def _popen(self: subprocess.Popen[Any], args: Any, *_: Any, **__: Any) -> tuple[str, bool]:
    words = args if isinstance(args, list | tuple) else [args]
    return f"started a subprocess {' '.join(str(w) for w in words[:3])!r}", _starts_the_browser(args)


_PATCHES: list[tuple[Any, str, Callable[..., tuple[str, bool]]]] = [
    (subprocess.Popen, "__init__", _popen),
    (os, "system", lambda command, *_, **__: (f"ran os.system({command!r})", False)),
    (os, "fork", lambda *_, **__: ("forked the process", False)),
    (os, "posix_spawn", lambda path, *_, **__: (f"spawned {path!r}", False)),
    (os, "posix_spawnp", lambda path, *_, **__: (f"spawned {path!r}", False)),
    (multiprocessing.process.BaseProcess, "start", lambda *_, **__: ("started a multiprocessing process", False)),
    (socket.socket, "listen", lambda sock, *_, **__: (f"listened on {sock.getsockname()!r} (a server)", False)),
]


def pytest_configure(config: pytest.Config) -> None:
    for owner, name, describe in _PATCHES:
        setattr(owner, name, _guarded(getattr(owner, name), describe))


def pytest_unconfigure(config: pytest.Config) -> None:
    for owner, name, _ in _PATCHES:
        current = getattr(owner, name)
        setattr(owner, name, getattr(current, "__wrapped__", current))


@pytest.hookimpl(wrapper=True)
def pytest_runtest_protocol(item: pytest.Item, nextitem: pytest.Item | None) -> Generator[None, object, object]:
    _running.append(item)
    try:
        return (yield)
    finally:
        _running.pop()


@pytest.hookimpl(wrapper=True)
def pytest_runtest_makereport(item: pytest.Item, call: pytest.CallInfo[None]) -> Generator[None, Any, Any]:
    """A test that started something its lane forbids fails, whatever else it did."""
    report = yield
    offences = _offences.pop(item.nodeid, None)
    if offences and report.when in ("call", "teardown"):
        report.outcome = "failed"
        report.longrepr = "the fast lane starts no process and no server; this test:\n  " + "\n  ".join(
            dict.fromkeys(offences)
        )
    elif offences:  # setup: keep them for the call's (or the teardown's) report
        _offences[item.nodeid] = offences
    return report
