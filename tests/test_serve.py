"""``rigidrel serve`` / ``python -m rigidrel_app`` as a user runs them: the URL it really got, clean exits."""

from __future__ import annotations

import contextlib
import os
import re
import signal
import socket
import subprocess
import sys
import time
import urllib.request
from collections.abc import Iterator
from pathlib import Path

import pytest

from tests.viser_client import shown

ROOT = Path(__file__).resolve().parents[1]
pytestmark = pytest.mark.slow
URL = re.compile(r"rigidrel: serving on (http://127\.0\.0\.1:(\d+))")


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def start(*args: str, sigint_ignored: bool = False) -> tuple[subprocess.Popen[str], str, int]:
    env = {**os.environ, "PYTHONUNBUFFERED": "1"}
    proc = subprocess.Popen(
        [sys.executable, *args],
        cwd=ROOT,
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
        env=env,
        # as a background job of a non-interactive shell (CI, nohup ... &) starts it
        preexec_fn=(lambda: signal.signal(signal.SIGINT, signal.SIG_IGN)) if sigint_ignored else None,
    )
    assert proc.stdout is not None
    deadline = time.monotonic() + 60
    seen = []
    while time.monotonic() < deadline:
        line = proc.stdout.readline()
        seen.append(line)
        m = URL.search(line)
        if m:
            return proc, m.group(1), int(m.group(2))
        if proc.poll() is not None:
            break
    proc.kill()
    pytest.fail("no URL printed:\n" + "".join(seen))


@contextlib.contextmanager
def serving(*args: str, sigint_ignored: bool = False) -> Iterator[tuple[subprocess.Popen[str], str, int]]:
    """``start`` whose process is killed on the way out, whatever the test did with it."""
    proc, url, port = start(*args, sigint_ignored=sigint_ignored)
    try:
        yield proc, url, port
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.communicate(timeout=20)


def stop(proc: subprocess.Popen[str], sig: int) -> str:
    proc.send_signal(sig)
    try:
        out, _ = proc.communicate(timeout=20)
    except subprocess.TimeoutExpired:
        proc.kill()
        pytest.fail("the server did not stop within 20 s")
    return out


@pytest.mark.parametrize("sig", [signal.SIGINT, signal.SIGTERM])
def test_serve_prints_its_url_and_stops_cleanly(sig: int) -> None:
    port = free_port()
    with serving("-m", "rigidrel_app.cli", "serve", "--port", str(port)) as (proc, url, got):
        assert got == port
        with urllib.request.urlopen(url, timeout=10) as r:
            assert r.status == 200 and b"<html" in r.read().lower()
        out = stop(proc, sig)
    assert proc.returncode == 0, out
    assert "shutting down" in out
    assert "Traceback" not in out


def test_ctrl_c_stops_the_server_even_when_started_with_sigint_ignored() -> None:
    """A shell's background job inherits SIGINT ignored; Ctrl-C (SIGINT) must still stop the server."""
    with serving("-m", "rigidrel_app.cli", "serve", "--port", str(free_port()), sigint_ignored=True) as (proc, _, _):
        out = stop(proc, signal.SIGINT)
    assert proc.returncode == 0, out
    assert "shutting down" in out


def test_busy_port_moves_on_and_says_where() -> None:
    with socket.socket() as blocker:
        blocker.bind(("127.0.0.1", 0))
        blocker.listen()
        busy = int(blocker.getsockname()[1])
        with serving("-m", "rigidrel_app", "--port", str(busy)) as (proc, url, got):
            assert got != busy
            with urllib.request.urlopen(url, timeout=10) as r:
                assert r.status == 200
            stop(proc, signal.SIGINT)
    assert proc.returncode == 0


def test_binds_loopback_by_default() -> None:
    from rigidrel_app.live.server import App

    with App(port=0) as app:
        assert app.server.get_host() == "127.0.0.1"
        assert app.url.startswith("http://127.0.0.1:")


@pytest.mark.parametrize("args", [["--port", "70000"], ["--port", "abc"], ["--host"]])
def test_bad_serve_arguments(args: list[str]) -> None:
    r = subprocess.run(
        [sys.executable, "-m", "rigidrel_app.cli", "serve", *args], capture_output=True, text=True, cwd=ROOT, timeout=60
    )
    assert r.returncode == 2
    assert len(r.stderr.splitlines()) == 1


def test_clean_shutdown_with_clients_connected_and_one_stalled() -> None:
    """SIGINT/SIGTERM while tabs are playing and one stopped reading: exit 0, no traceback, in time."""
    from tests.viser_client import ClientLoop, LightClient, wait_until

    loop = ClientLoop()  # pytest may already run an event loop in this thread: playwright's
    try:
        for sig in (signal.SIGINT, signal.SIGTERM):
            with serving("-m", "rigidrel_app.cli", "serve", "--port", str(free_port())) as (proc, url, _):
                clients = [LightClient(url) for _ in range(3)] + [LightClient(url, read=False)]
                for c in clients:
                    loop.run(c.connect(), timeout=30)
                readers = [loop.start(c.run(30)) for c in clients]
                # the reading tabs press Play once their controls have come, and their rods move
                for c in clients[:3]:
                    wait_until(lambda c=c: "Play" in c.gui_uuid, timeout=30)
                    loop.run(c.set_value("Play", True), timeout=30)
                wait_until(lambda clients=clients: all(c.stats.lane_frames > 1 for c in clients[:3]), timeout=30)
                t0 = time.monotonic()
                out = stop(proc, sig)
                took = time.monotonic() - t0
                for c in clients:
                    c.stop()
                for r in readers:
                    r.result(30)
            assert proc.returncode == 0, out
            # a client dropped by the shutdown is one "rigidrel: dropped ..." line; nothing else may fail
            others = [line for line in out.splitlines() if not line.startswith("rigidrel: dropped")]
            assert not any("Traceback" in line or "Error" in line for line in others), out
            assert took < 15.0
    finally:
        loop.close()


def test_serve_with_a_scene_opens_every_tab_on_that_state() -> None:
    """``rigidrel serve rod-collision --mass2 3 --frame 0.4 --t 0.25 --layers all``, a scenario line as
    the app's Scenario folder writes it: a new tab shows that scene in that frame, at that time."""
    from rigidrel_app.cli import build_parser, start_scenario
    from rigidrel_app.live.server import App
    from rigidrel_app.view.layers import Layer
    from rigidrel_app.view.scenario import parse_scenario
    from tests.viser_client import light_tab

    line = ["rod-collision", "--mass2", "3", "--frame", "0.4", "--t", "0.25", "--layers", "all"]
    args = build_parser().parse_args(["serve", *line, "--port", "0"])
    start = start_scenario("rigidrel serve", args)
    assert start is not None and args.port == 0
    assert start == parse_scenario(" ".join(line))  # the app's scenario box reads the same line
    with App(port=0, start=start) as app, light_tab(app) as tab:
        session, drawn = tab.session, tab.session.painter.drawn
        assert session.state.settings == start.settings and drawn is not None
        assert drawn.resolved.scene.parameters["mass2"] == 3.0
        assert drawn.resolved.frame.beta == 0.4
        assert session.state.settings.layers == frozenset(Layer)
        assert session.state.playback.now == 0.25 and not session.state.playback.playing


def test_a_slider_redraw_draws_and_places_once(monkeypatch: pytest.MonkeyPatch) -> None:
    """The pole in the barn in presenter mode on a short canvas (its lane titles are too long for one
    line, and its legend needs more rows than the default): once the session has laid it out, a
    slider's redraw builds the drawing once and the canvas places no label again."""
    from rigidrel_app.live.server import App
    from rigidrel_app.view import canvas
    from rigidrel_app.view import page as page_module
    from rigidrel_app.view.layout import LEGEND_ROWS, CanvasSize
    from rigidrel_app.view.state import Settings
    from tests.viser_client import light_tab

    with App(port=0) as app, light_tab(app) as tab:
        session = tab.session
        session.asks.set_presenter(True)
        with session.lock:
            session.resize(CanvasSize.measured_by_page(1240, 560, 1.0))
        session.asks.change(Settings("pole-barn"))
        layout = session.painter.layout
        assert layout is not None and layout.lanes[0].title_lines >= 2 and session.painter.legend_rows != LEGEND_ROWS
        builds, placements = [], []
        build, place = page_module.build_drawing, canvas.place_labels
        monkeypatch.setattr(page_module, "build_drawing", lambda *a, **k: builds.append(1) or build(*a, **k))
        monkeypatch.setattr(canvas, "place_labels", lambda *a, **k: placements.append(1) or place(*a, **k))
        session.asks.change(session.state.settings.with_value("v", 0.7))
        assert (len(builds), len(placements)) == (1, 0)


def test_pointer_events_are_taken_once_each_in_their_order() -> None:
    """A report callback reads the report box's newest value, so the same events may come twice and a
    later report's may come first: each pointer event is taken once, in its order. A click on an
    event's dot draws its cone; the same report read again does not take it away; a second click does."""
    import json

    from rigidrel_app.live.runtime import parse_report
    from rigidrel_app.live.server import App
    from rigidrel_app.view.scenario import Scenario
    from rigidrel_app.view.state import Settings
    from tests.viser_client import light_tab

    with App(port=0, start=Scenario(Settings("rod-collision"))) as app, light_tab(app) as tab:
        session = tab.session
        layout, drawn = session.painter.layout, session.painter.drawn
        assert layout is not None and drawn is not None
        lab = shown(session.painter.chart_frames[0])
        name, (t, x) = next(iter(drawn.resolved.scene.events_in().items()))
        px, pz = lab.px_one(x, t)
        y = layout.height - pz  # the canvas' CSS px, y down

        def report(run: str, *events: tuple[int, str]) -> None:
            text = json.dumps({"event": "pointer", "run": run, "events": [
                {"seq": seq, "phase": phase, "x": px, "y": y} for seq, phase in events]})  # fmt: skip
            parsed = parse_report(text)
            assert parsed is not None
            with session.lock:
                session.gestures.reported(parsed)

        report("a", (1, "down"), (2, "up"))
        assert session.state.settings.cone == name
        report("a", (1, "down"), (2, "up"))  # read again: nothing new
        assert session.state.settings.cone == name
        report("a", (1, "down"), (2, "up"), (3, "down"), (4, "up"))
        assert session.state.settings.cone is None
        report("b", (1, "down"), (2, "up"))  # a new runtime numbers from 1
        assert session.state.settings.cone == name
