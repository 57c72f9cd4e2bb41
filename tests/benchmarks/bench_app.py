"""Speed of the app, server side and in the browser (a script that prints figures, not a test).

    python -m tests.benchmarks.bench_app [--seconds 10] [--clients 1 10] [--no-browser]

* rebuild: a slider change to every drawing rebuilt (scene, diagrams, lanes), median
  per scene, timed in the server process (target <= 16 ms);
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
from dataclasses import replace

import numpy as np

import rigidrel_core as rr
from rigidrel_app.live.server import ANIMATION_HZ, App
from rigidrel_app.view.state import CUSTOM_FRAME, Settings, resolve
from tests import load
from tests.viser_client import ClientLoop, LightClient, wait_until


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


def bench_rebuild() -> dict[str, float]:
    out: dict[str, float] = {}
    loop = ClientLoop()
    with App(port=0) as app:
        client = LightClient(app.url)
        loop.run(client.connect())
        loop.start(client.run(3600))
        wait_until(lambda: app.sessions, timeout=60)
        session = next(iter(app.sessions.values()))
        for kind in rr.scene_descriptions():
            session.change(Settings(kind))
            times = []
            for name, value in slider_sweep(kind):
                s = session.settings
                new = replace(s, frame=CUSTOM_FRAME, beta=value) if name == "beta" else s.with_value(name, value)
                if isinstance(resolve(new), str):  # a combination that makes no scene (V1 <= V2): not a rebuild
                    continue
                t0 = time.perf_counter()
                session.change(new)  # what a slider's callback does
                times.append(time.perf_counter() - t0)
            out[f"rebuild_median_ms[{kind}]"] = 1e3 * statistics.median(times)
            out[f"rebuild_max_ms[{kind}]"] = 1e3 * max(times)
        client.stop()
        loop.run(client.close())
    loop.close()
    return out


def bench_animation(n_clients: int, seconds: float) -> dict[str, float]:
    """The load benchmark's run (tests/load.py) at the app's own animation rate."""
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
    args = parser.parse_args()
    figures: dict[str, float] = {}
    figures.update(bench_rebuild())
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
