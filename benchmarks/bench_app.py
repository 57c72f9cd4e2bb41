"""Speed of the app, server side and in the browser (a script that prints figures, not a test).

    python -m benchmarks.bench_app [--seconds 10] [--clients 1 10] [--no-browser] [--drawing] [--answer]
    python -m benchmarks.bench_app --phases [--runtime]

* rebuild: a slider change to every drawing rebuilt (scene, diagrams, lanes), median
  per scene, timed in the server process (target <= 16 ms); ``--phases`` prints only where
  it goes (:func:`bench_phases`);
* answer: a slider value sent by a client, from the server's socket receiving it to the
  server's socket sending the last frame of the answer (target <= 10 ms), with the session
  flushing its answer and, alternated with it, without (viser's 1/60 s send window);
* drawing (only with ``--drawing``, which prints nothing else): what the answer's redraw computes, without viser,
  over the answer's values, at the pace of clicks and back to back (:func:`bench_drawing`);
* animation: N lightweight viser clients (another process) playing at once: delivered
  rod frames per second per client (target >= 30) and server CPU per client (target <= 15 %
  of one core);
* first frame: headless Chromium, from ``page.goto`` to the first canvas pixels of a rod.
"""

from __future__ import annotations

import argparse
import io
import json
import math
import statistics
import time
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

import rigidrel_core as rr
from benchmarks import load
from rigidrel_app.live.painting import PaintingCache
from rigidrel_app.live.server import ANIMATION_HZ, App
from rigidrel_app.view.state import CUSTOM_FRAME, Settings, resolve
from tests.viser_client import LightClient, RuntimeClient, light_tab, wait_until


def slider_sweep(kind: str) -> list[tuple[str, float]]:
    """Eight values across each slider of the scene (from its description), then the custom frame's β."""
    sweep: list[tuple[str, float]] = []
    for p in rr.describe(kind).parameters:
        if p.slider is None:
            continue
        lo, hi = p.slider.lo, p.slider.hi
        values = np.geomspace(lo, hi, 8) if p.slider.scale == "log" else np.linspace(lo, hi, 8)
        sweep += [(p.name, float(v)) for v in values]
    return sweep + [("beta", float(b)) for b in np.linspace(-0.9, 0.9, 6)]


def sweep_settings(start: Settings) -> list[Settings]:
    """The settings a tab passes through as :func:`slider_sweep` moves its sliders one value after
    another from ``start`` (each from the one before), leaving out those that make no scene (V1 <= V2)."""
    out: list[Settings] = []
    s = start
    for name, value in slider_sweep(start.scene):
        new = replace(s, frame=CUSTOM_FRAME, beta=value) if name == "beta" else s.with_value(name, value)
        if not isinstance(resolve(new), str):
            out.append(new)
            s = new
    return out


def bench_rebuild() -> dict[str, float]:
    out: dict[str, float] = {}
    with App(port=0) as app, light_tab(app) as tab:
        session = tab.session
        for kind in rr.scene_descriptions():
            session.asks.change(Settings(kind))
            times = []
            for new in sweep_settings(session.state.settings):
                t0 = time.perf_counter()
                session.asks.change(new)  # what a slider's callback does
                times.append(time.perf_counter() - t0)
            out[f"rebuild_median_ms[{kind}]"] = 1e3 * statistics.median(times)
            out[f"rebuild_max_ms[{kind}]"] = 1e3 * max(times)
    return out


#: The steps of a slider's redraw timed by :func:`bench_phases`: (label, module, attribute). Each is
#: a function the session calls (by its own module's name for it, or as a method).
PHASES = (
    ("page laid out", "rigidrel_app.live.painting", "lay_out"),
    ("  its drawing", "rigidrel_app.view.page", "build_drawing"),
    ("    its label placement", "rigidrel_app.view.diagrams", "place_labels"),
    ("  its still picture", "rigidrel_app.view.page", "still_picture"),
    ("lanes drawn (page and instant)", "rigidrel_app.view.scene_view", "Drawn.lane_pictures"),
    ("static layer sent", "rigidrel_app.backends.viser", "PageRenderer.set_static"),
    ("labels sent (static and moving)", "rigidrel_app.backends.viser", "_Texts.show"),
    ("instant drawn", "rigidrel_app.live.session", "Session.draw_now"),
    ("  its lanes and moving parts sent", "rigidrel_app.backends.viser", "PageRenderer.update"),
    ("  its frame to the runtime", "rigidrel_app.live.timeline", "Mirror.frame"),
    ("legend", "rigidrel_app.view.scene_view", "Drawn.legend"),
    ("words said", "rigidrel_app.live.page_words", "PageWords.say"),
    ("controls shown", "rigidrel_app.live.controls", "Controls.show"),
    ("camera", "rigidrel_app.live.painter", "Painter.fit_camera"),
)


def bench_phases(kinds: tuple[str, ...] | None = None, runtime: bool = False) -> dict[str, float]:
    """Where a slider's redraw goes: the sweep of :func:`bench_rebuild` for each scene, made twice
    (the second timed, back to back), each of :data:`PHASES` timed by wrapping the function the
    session calls; the total's median and each phase's mean, per scene, in ms. ``runtime``: the
    tab has the playback runtime (as a browser's has), as in :func:`bench_answer`."""
    import importlib

    spent: dict[str, float] = {}

    def timed(label: str, f: Any) -> Any:
        def wrapper(*args: Any, **kwargs: Any) -> Any:
            t0 = time.perf_counter()
            try:
                return f(*args, **kwargs)
            finally:
                spent[label] = spent.get(label, 0.0) + time.perf_counter() - t0

        return wrapper

    originals: list[tuple[Any, str, Any]] = []
    for label, module_name, attribute in PHASES:
        owner: Any = importlib.import_module(module_name)
        *path, name = attribute.split(".")
        for part in path:
            owner = getattr(owner, part)
        originals.append((owner, name, getattr(owner, name)))
        setattr(owner, name, timed(label, getattr(owner, name)))
    out: dict[str, float] = {}
    try:
        with App(port=0) as app, light_tab(app, RuntimeClient if runtime else LightClient) as tab:
            session = tab.session
            wait_until(lambda: session.player.ready == runtime, timeout=60)
            for kind in kinds or tuple(rr.scene_descriptions()):
                session.asks.change(Settings(kind))
                sweep = sweep_settings(session.state.settings)
                for new in sweep:
                    session.asks.change(new)
                session.asks.change(Settings(kind))
                session.painter.paintings = PaintingCache()  # every value drawn again, as a new one is
                spent.clear()
                times = []
                for new in sweep:
                    t0 = time.perf_counter()
                    session.asks.change(new)
                    times.append(time.perf_counter() - t0)
                out[f"redraw_median_ms[{kind}]"] = 1e3 * statistics.median(times)
                for label, _, _ in PHASES:
                    out[f"phase_mean_ms[{kind}][{label}]"] = 1e3 * spent.get(label, 0.0) / len(sweep)
    finally:
        for owner, name, original in originals:
            setattr(owner, name, original)
    return out


class SocketClock:
    """Times the server's own websocket for one client: when each message came in (``received``)
    and when each frame had been handed to the socket (``sent``), in ``time.perf_counter`` s."""

    def __init__(self, connection: Any) -> None:
        self.received: list[float] = []
        self.sent: list[float] = []
        recv, send = connection.recv, connection.send

        async def timed_recv(*args: Any, **kwargs: Any) -> Any:
            data = await recv(*args, **kwargs)
            self.received.append(time.perf_counter())
            return data

        async def timed_send(*args: Any, **kwargs: Any) -> None:
            await send(*args, **kwargs)
            self.sent.append(time.perf_counter())

        connection.recv, connection.send = timed_recv, timed_send


def bench_answer(per_scene: int = 6, quiet: float = 0.15, runtime: bool = False) -> dict[str, float]:
    """A slider moved by a client of a paused tab: message in -> last frame of the answer out, on the
    server's socket. Flushed (what the session does) and not flushed (viser's send window) alternate,
    value by value, over ``per_scene`` values of each linear slider of every scene. Also split: the
    callback's redraw (``Session.ask``), and from its end to the last frame out. ``runtime``: the
    tab has the playback runtime (as a browser's has: the moving parts go to it as one still frame),
    else the server draws them into the tab's scene."""
    times: dict[str, list[float]] = {"flushed": [], "window": []}
    after_redraw: dict[str, list[float]] = {"flushed": [], "window": []}
    redraws: list[float] = []
    with App(port=0) as app, light_tab(app, RuntimeClient if runtime else LightClient) as tab:
        session, client, loop = tab.session, tab.client, tab.loop
        wait_until(lambda: "V" in client.gui_uuid and session.player.ready == runtime, timeout=60)
        connection = app.server._websock_server._live_connections[session.client.client_id]
        clock = SocketClock(connection)
        handled = session.messages_handled
        # the consumer was already waiting in the untimed recv: one message to move it on
        loop.run(
            client.send_raw({"type": "GuiUpdateMessage", "uuid": client.gui_uuid["Speed"], "updates": {"value": 1.5}})
        )
        wait_until(lambda: session.messages_handled > handled)
        flush, ask = session.client.flush, session.ask
        changed: list[tuple[float, float]] = []

        def timed_ask(*args: Any, **kwargs: Any) -> None:
            t0 = time.perf_counter()
            ask(*args, **kwargs)
            changed.append((t0, time.perf_counter()))

        previous = ""
        for k, v in enumerate(answer_values(per_scene)):
            if v.settings.scene != previous:
                session.asks.change(Settings(v.settings.scene))
                previous = v.settings.scene
            control = session.controls.parameters[v.parameter].slider
            variant = ("flushed", "window")[k % 2]
            session.client.flush = flush if variant == "flushed" else (lambda: None)  # type: ignore[method-assign]
            time.sleep(quiet)
            n_in, handled = len(clock.received), session.messages_handled
            message = {"type": "GuiUpdateMessage", "uuid": control._impl.uuid, "updates": {"value": v.value}}
            session.ask = timed_ask  # type: ignore[method-assign]
            loop.run(client.send_raw(message))
            wait_until(lambda h=handled: session.messages_handled > h, interval=0.005)
            session.ask = ask  # type: ignore[method-assign]
            assert session.state.settings == v.settings, (session.state.settings, v.settings)
            t_in = clock.received[n_in]

            def answered(t: float = t_in) -> bool:  # sent, then quiet for ``quiet`` s
                return bool(clock.sent) and time.perf_counter() - max(clock.sent[-1], t) > quiet

            wait_until(answered, interval=0.01)
            times[variant].append(clock.sent[-1] - t_in)
            redraw_start, redraw_end = changed[-1]
            redraws.append(redraw_end - redraw_start)
            after_redraw[variant].append(clock.sent[-1] - redraw_end)
        session.client.flush = flush  # type: ignore[method-assign]
    out: dict[str, float] = {}
    if runtime:
        times = {f"{k}, runtime": v for k, v in times.items()}
        after_redraw = {f"{k}, runtime": v for k, v in after_redraw.items()}
    for variant, ts in times.items():
        out[f"answer_ms_median[{variant}]"] = 1e3 * statistics.median(ts)
        out[f"answer_ms_p90[{variant}]"] = 1e3 * float(np.percentile(ts, 90))
        out[f"answer_ms_max[{variant}]"] = 1e3 * max(ts)
        out[f"answer_after_redraw_ms_median[{variant}]"] = 1e3 * statistics.median(after_redraw[variant])
    suffix = "[runtime]" if runtime else ""
    out[f"answer_redraw_ms_median{suffix}"] = 1e3 * statistics.median(redraws)
    out[f"answer_samples{suffix}"] = float(sum(len(ts) for ts in times.values()))
    return out


@dataclass(frozen=True)
class AnswerValue:
    """One value :func:`bench_answer` sends to a slider."""

    parameter: rr.Parameter
    value: float
    settings: Settings
    """The tab's settings once it has taken the value."""


def answer_values(per_scene: int = 6) -> list[AnswerValue]:
    """What :func:`bench_answer` sends, in its order: ``per_scene`` values across each linear slider
    of every scene (each scene from its defaults), each value taken from the settings the one
    before left, leaving out those that make no scene."""
    out: list[AnswerValue] = []
    for kind in rr.scene_descriptions():
        s = Settings(kind)
        for p in rr.describe(kind).parameters:
            if p.slider is None or p.slider.scale == "log":
                continue
            for value in np.linspace(p.slider.lo, p.slider.hi, per_scene):
                new = s.with_value(p.name, float(value))
                if not isinstance(resolve(new), str):
                    out.append(AnswerValue(p, float(value), new))
                    s = new
    return out


def bench_drawing(repeats: int = 2, quiet: float = 0.15) -> dict[str, float]:
    """The drawing a slider's answer makes, without viser: what ``Session.apply`` and its
    ``draw_now`` compute (the scene, the three charts with their labels placed, their pictures, the
    legend, the lanes and the moving parts) on the 960 x 720 canvas of :func:`bench_answer`'s tab, over the
    values of :func:`answer_values`; each made ``quiet`` s after the last (as clicks come) and
    back to back, alternated ``repeats`` times. Medians and p90 in ms: the part of the answer that
    no message costs."""
    from rigidrel_app.view.canvas import legend_rows, moving_picture, still_picture
    from rigidrel_app.view.layout import NORMAL, canvas_layout
    from rigidrel_app.view.scene_view import build_drawing

    layout = canvas_layout(960.0, 720.0, NORMAL)  # the canvas the benchmarks' light tab reports

    def draw(s: Settings) -> None:
        resolved = resolve(s)
        assert not isinstance(resolved, str)
        d = build_drawing(resolved, areas=layout.chart_areas, label_px=layout.theme.text_px)
        legend = d.legend()
        legend_rows(legend, layout.legend.width, layout.theme)
        frames, _ = still_picture(d.charts, layout.charts, legend, layout.legend, layout.theme)
        lanes = d.lane_pictures(d.window[0], layout)
        moving_picture(frames, d.moving_items(d.window[0], [lane.ends for lane in lanes]), layout.theme)

    values = [v.settings for v in answer_values()]
    for s in values[:30]:  # warm
        draw(s)
    times: dict[str, list[float]] = {"idle": [], "back_to_back": []}
    for _ in range(repeats):
        for variant in times:
            for s in values:
                if variant == "idle":
                    time.sleep(quiet)
                t0 = time.perf_counter()
                draw(s)
                times[variant].append(time.perf_counter() - t0)
    out: dict[str, float] = {}
    for variant, ts in times.items():
        out[f"drawing_ms_median[{variant}]"] = 1e3 * statistics.median(ts)
        out[f"drawing_ms_p90[{variant}]"] = 1e3 * float(np.percentile(ts, 90))
    out["drawing_samples"] = float(len(values))
    return out


def bench_animation(n_clients: int, seconds: float) -> dict[str, float]:
    """The load benchmark's run (benchmarks/load.py) at the app's own animation rate."""
    r = load.run(n_clients, seconds, ANIMATION_HZ)
    n = n_clients
    return {
        f"animation_clients[{n}]": r["clients"],
        f"animation_fps_min[{n}]": r["min_fps"],
        f"animation_fps_median[{n}]": r["median_fps"],
        f"server_cpu_percent_per_client[{n}]": r["cpu_percent_per_client"],
        f"kbytes_per_second_per_client[{n}]": r["kbytes_per_second_per_client"],
        f"errors[{n}]": r["errors"],
    }


def bench_first_frame(repeats: int = 3) -> dict[str, float]:
    from PIL import Image
    from playwright.sync_api import sync_playwright

    from tests.browser.conftest import VIEWPORT, launch_chromium

    times = []
    with App(port=0) as app, sync_playwright() as p:
        browser = launch_chromium(p)
        for _ in range(repeats):
            page = browser.new_page(viewport=VIEWPORT)
            t0 = time.perf_counter()
            page.goto(app.url)
            while True:
                canvas = page.locator("canvas[data-engine]")
                if canvas.count():
                    img = np.asarray(Image.open(io.BytesIO(canvas.screenshot())).convert("RGB")).astype(int)
                    if ((img[..., 2] - img[..., 0]) > 100).sum() > 500:  # the blue rod is drawn
                        break
                if time.perf_counter() - t0 > 120:
                    raise TimeoutError("no rod on the canvas")
                time.sleep(0.05)
            times.append(time.perf_counter() - t0)
            page.close()
        browser.close()
    return {
        "page_open_to_first_rod_frame_s_median": statistics.median(times),
        "page_open_to_first_rod_frame_s_max": max(times),
    }


def main() -> None:
    parser = argparse.ArgumentParser(description="rigidrel app speed figures")
    parser.add_argument("--seconds", type=float, default=10.0)
    parser.add_argument("--clients", type=int, nargs="+", default=[1, 10])
    parser.add_argument("--no-browser", action="store_true")
    parser.add_argument("--json", action="store_true")
    parser.add_argument("--phases", action="store_true", help="only where a slider's redraw goes, per scene")
    parser.add_argument("--runtime", action="store_true", help="with --phases: the tab has the playback runtime")
    parser.add_argument("--drawing", action="store_true", help="only the answer's drawing, without viser")
    parser.add_argument("--answer", action="store_true", help="only a slider's answer, without and with the runtime")
    args = parser.parse_args()
    figures: dict[str, float] = {}
    if args.phases:
        figures.update(bench_phases(runtime=args.runtime))
        for k, v in figures.items():
            print(f"{k:70s} {v:8.2f}")
        return
    if args.drawing:
        for k, v in bench_drawing().items():
            print(f"{k:40s} {v:8.2f}")
        return
    if args.answer:
        for runtime in (False, True):
            for k, v in bench_answer(runtime=runtime).items():
                print(f"{k:58s} {v:10.2f}", flush=True)
        return
    figures.update(bench_rebuild())
    figures.update(bench_answer())
    for n in args.clients:
        figures.update(bench_animation(n, args.seconds))
    if not args.no_browser:
        figures.update(bench_first_frame())
    if args.json:
        print(json.dumps(figures, indent=2))
    else:
        for k, v in figures.items():
            print(f"{k:58s} {v:10.2f}" if math.isfinite(v) else f"{k:58s} {v}")


if __name__ == "__main__":
    main()
