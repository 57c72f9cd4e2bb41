"""The floor under the app's playback rate: how fast headless Chromium (software WebGL) draws a
viser page that holds almost nothing. A script, not a test (numbers vary with the machine's load):

    python -m benchmarks.browser.measure_floor [--labels 0 30 60 120] [--width 1280 --height 720]

A bare viser server (none of rigidrel's page) shows one box that moves 40 times a second, as the
app's playback does, and ``--labels`` screen-space labels that never change. The frames per second
are counted as :data:`COUNT_FRAMES` counts them (``requestAnimationFrame`` ticks in
which the page handled a new websocket message), over ``--seconds`` after the page has drawn for
two seconds. What an empty page reaches is the most the app's page, which adds its lanes, diagrams
and about a hundred labels on top, can reach in this browser.
"""

from __future__ import annotations

import argparse
import threading
import time

import numpy as np
import viser

from tests.browser.conftest import launch_chromium
from tests.viser_client import wait_until

#: Counts, in the page: websocket messages handled, animation frames, and animation frames that
#: handled a new message (a new picture).
COUNT_FRAMES = """
window.__msgs = 0; window.__frames = 0; window.__ticks = 0; window.__times = [];
(() => {
  const Orig = window.WebSocket;
  function Counted(...args) {
    const ws = new Orig(...args);
    ws.addEventListener('message', (e) => {
      window.__msgs++; window.__times.push(performance.now());
    });
    return ws;
  }
  Counted.prototype = Orig.prototype;
  Object.assign(Counted, {CONNECTING: 0, OPEN: 1, CLOSING: 2, CLOSED: 3});
  window.WebSocket = Counted;
  // viser reads its websocket in a worker: count what the worker hands the page
  const OrigWorker = window.Worker;
  function CountedWorker(...args) {
    const w = new OrigWorker(...args);
    w.addEventListener('message', () => { window.__msgs++; window.__times.push(performance.now()); });
    return w;
  }
  CountedWorker.prototype = OrigWorker.prototype;
  window.Worker = CountedWorker;
  let last = 0;
  function loop() {
    window.__ticks++;
    if (window.__msgs !== last) { window.__frames++; last = window.__msgs; }
    requestAnimationFrame(loop);
  }
  requestAnimationFrame(loop);
})();
"""

#: The app's playback rate (pictures sent per second).
SEND_HZ = 40.0
#: Seconds the page plays before it is measured: viser lowers its resolution in steps of 2.5 s
#: while frames come slower than 38 a second (its adaptive resolution), twice at most.
WARM_S = 8.0


def measure(labels: int, width: int, height: int, seconds: float, moving: bool = False) -> dict[str, float]:
    """``moving``: the labels move and change their text every picture too (the bare page the
    app's playback is compared with: one moving box, 16 moving labels)."""
    from playwright.sync_api import sync_playwright

    server = viser.ViserServer(host="127.0.0.1", port=0, verbose=False)
    done = threading.Event()
    box = server.scene.add_box("/box", color=(0, 114, 178), dimensions=(0.3, 0.1, 0.1))
    handles = []
    for k in range(labels):
        angle = 2.0 * np.pi * k / max(labels, 1)
        position = (1.5 * np.cos(angle), 0.0, np.sin(angle))
        handles.append(server.scene.add_label(f"/label/{k}", f"label {k}", position=position, font_screen_scale=1.25))

    def play() -> None:
        k = 0
        while not done.wait(1.0 / SEND_HZ):
            with server.atomic():
                box.position = (float(np.sin(k / 20.0)), 0.0, 0.0)
                if moving:
                    for j, h in enumerate(handles):
                        angle = 2.0 * np.pi * j / max(labels, 1) + k / 40.0
                        h.position = (1.5 * np.cos(angle), 0.0, np.sin(angle))
                        h.text = f"t = {k / SEND_HZ:+.3f}"
            server.flush()
            k += 1

    player = threading.Thread(target=play, daemon=True)
    player.start()
    try:
        with sync_playwright() as p:
            browser = launch_chromium(p)
            try:
                page = browser.new_page(viewport={"width": width, "height": height})
                page.add_init_script(COUNT_FRAMES)
                page.goto(f"http://127.0.0.1:{server.get_port()}/")
                wait_until(lambda: page.evaluate("() => window.__frames") > 0, timeout=120)
                time.sleep(WARM_S)  # warm: viser's adaptive resolution settles
                f0, k0, m0 = page.evaluate("() => [window.__frames, window.__ticks, window.__msgs]")
                time.sleep(seconds)
                f1, k1, m1 = page.evaluate("() => [window.__frames, window.__ticks, window.__msgs]")
            finally:
                browser.close()
    finally:
        done.set()
        player.join()
        server.stop()
    return {
        "labels": float(labels),
        "fps": (f1 - f0) / seconds,
        "animation_frames_per_s": (k1 - k0) / seconds,
        "messages_per_s": (m1 - m0) / seconds,
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--labels", type=int, nargs="+", default=[0, 30, 60, 120])
    parser.add_argument("--width", type=int, default=1280)
    parser.add_argument("--height", type=int, default=720)
    parser.add_argument("--seconds", type=float, default=5.0)
    args = parser.parse_args()
    for n in args.labels:
        r = measure(n, args.width, args.height, args.seconds)
        print(f"{args.width}x{args.height} " + " ".join(f"{k}={v:.1f}" for k, v in r.items()), flush=True)


if __name__ == "__main__":
    main()
