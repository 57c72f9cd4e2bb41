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

import numpy as np

import rigidrel_core as rr
from app.server import ANIMATION_HZ, App
from tests import load
from tests.viser_client import ClientLoop, LightClient, wait_until

SLIDER_SWEEPS: dict[rr.SceneKind, list[tuple[str, object]]] = {
    rr.SceneKind.CONSTANT_ACCELERATION: [("v", v) for v in np.linspace(0.1, 0.95, 12)]
    + [("a_front_length", a) for a in np.linspace(0.1, 0.95, 8)],
    rr.SceneKind.DECELERATION: [("v", v) for v in np.linspace(0.1, 0.95, 12)],
    rr.SceneKind.IMPULSIVE_START: [("v", v) for v in np.linspace(0.1, 0.95, 12)],
    rr.SceneKind.WALL_COLLISION: [("v", v) for v in np.linspace(0.1, 0.95, 8)]
    + [("eps", e) for e in np.linspace(0.0, 1.0, 8)],
    rr.SceneKind.ROD_COLLISION: [("v", v) for v in np.linspace(0.3, 0.95, 8)]
    + [("log_mass_ratio", m) for m in np.linspace(-2, 2, 8)]
    + [("eps", e) for e in np.linspace(0.0, 1.0, 6)]
    + [("beta", b) for b in np.linspace(-0.9, 0.9, 6)],
}


def bench_rebuild() -> dict[str, float]:
    out: dict[str, float] = {}
    loop = ClientLoop()
    with App(port=0) as app:
        client = LightClient(app.url)
        loop.run(client.connect())
        loop.start(client.run(3600))
        wait_until(lambda: app.sessions, timeout=60)
        session = next(iter(app.sessions.values()))
        for kind, sweep in SLIDER_SWEEPS.items():
            session.change("scene", kind)
            times = []
            for field, value in sweep:
                t0 = time.perf_counter()
                session.change(field, float(value))  # type: ignore[arg-type]
                times.append(time.perf_counter() - t0)
            out[f"rebuild_median_ms[{kind.value}]"] = 1e3 * statistics.median(times)
            out[f"rebuild_max_ms[{kind.value}]"] = 1e3 * max(times)
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
