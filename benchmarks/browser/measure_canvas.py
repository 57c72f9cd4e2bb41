"""Measure one tab of the app in headless Chromium: bytes until the first picture, playback fps, and
slider-to-redraw time. A script, not a test (numbers vary with the machine's load):

    python -m benchmarks.browser.measure_canvas [--width 1280 --height 720 --seconds 5]

* bytes: websocket payload the page receives from connecting until the server has sent its first
  complete drawing and 1 s has passed quietly.
* fps: new pictures the tab shows per second, over ``--seconds`` of playback of the paper's Fig. 3
  after ``--warm`` seconds of it, at the given viewport (the diagrams visible): the frames the
  page's playback runtime applies (each a new picture, drawn in the next animation frame); for a
  page without the runtime, ``requestAnimationFrame`` ticks in which the page handled at least one
  new websocket message. Also the page's animation frames per second and messages per second.
* ``--pairs N``: N runs of the app, each right after a run of a bare viser page in the same browser
  (one moving box and 16 moving labels sent at the app's 40 frames a second, counted the same way:
  :func:`benchmarks.browser.measure_floor.measure`), and the medians and their ratio.
* slider-to-redraw: from the Enter that submits V = 0.85 in its box to the last websocket message
  of the redraw the page handles (messages closer than 60 ms counted as one burst); median of 5
  (with the panel shown, after a presenter-mode run).
* smallest text: the smallest text on the canvas (CSS px) as laid out for the played scene.

``--theme dark`` plays in the dark projector theme (the canvas inverted by the page's style),
``--presenter`` in presenter mode (key F).
"""

from __future__ import annotations

import argparse
import statistics
import time
from typing import Any

from benchmarks.browser.measure_floor import COUNT_FRAMES
from benchmarks.browser.measure_floor import measure as measure_bare
from rigidrel_app.live.server import App
from rigidrel_app.view.state import presets
from rigidrel_app.view.vocabulary import Shade
from tests.browser.conftest import launch_chromium
from tests.viser_client import wait_until

#: The pictures shown so far (the runtime's applied frames, else the frames with a new message),
#: animation frames and messages.
COUNTS = """() => [
  window.__rigidrelPlayback && window.__rigidrelPlayback.stats.frames ? window.__rigidrelPlayback.stats.frames
    : window.__frames,
  window.__ticks, window.__msgs]"""


def _width(session: Any) -> float:
    """The width the tab's page is laid out for (0 before it is)."""
    return 0.0 if session.painter.layout is None else float(session.painter.layout.width)


def measure(
    width: int, height: int, seconds: float, shade: Shade = "light", presenter: bool = False, warm: float = 2.0
) -> dict[str, float]:
    from playwright.sync_api import sync_playwright

    with App(port=0, shade=shade) as app, sync_playwright() as p:
        browser = launch_chromium(p)
        try:
            page = browser.new_page(viewport={"width": width, "height": height})
            page.add_init_script(COUNT_FRAMES)
            received: list[tuple[float, int]] = []

            def on_socket(ws: Any) -> None:
                ws.on("framereceived", lambda payload: received.append((time.monotonic(), len(payload or b""))))

            page.on("websocket", on_socket)
            page.goto(app.url)
            page.wait_for_selector("label:text-is('Scene')", timeout=60_000)
            session = wait_until(lambda: next(iter(app.sessions.values()), None), timeout=60)
            wait_until(lambda: session.painter.drawn is not None, timeout=60)

            def quiet() -> bool:
                return bool(received) and time.monotonic() - received[-1][0] > 1.0

            wait_until(quiet, timeout=60, interval=0.1)
            first_bytes = sum(n for _, n in received)
            for button in page.locator(".mantine-Notification-root button").all():
                button.click()
            if presenter:
                page.evaluate("() => document.activeElement && document.activeElement.blur()")
                page.keyboard.press("f")
                wait_until(lambda: session.state.presenter and _width(session) > 0.9 * width, timeout=60)
            with session.lock:
                session.asks.change(presets()["Fig. 3: collision, M2 = 2 M1"], refit=True)
                layout = session.painter.layout
                assert layout is not None
                smallest = min([t.px for t in session.painter.renderer.still.texts] + [layout.theme.text_px])
                session.asks.toggle_play()
            time.sleep(warm)  # warm (viser's adaptive resolution steps every 2.5 s at most)
            f0, k0, m0 = page.evaluate(COUNTS)
            time.sleep(seconds)
            f1, k1, m1 = page.evaluate(COUNTS)
            with session.lock:
                session.asks.toggle_play()
            if presenter:
                page.evaluate("() => document.activeElement && document.activeElement.blur()")
                page.keyboard.press("f")
                wait_until(lambda: not session.state.presenter and _width(session) < 0.9 * width, timeout=60)
            time.sleep(1.0)
            redraws = []
            # the control's own text box (viser's text box label names no id: the input after it)
            box = page.locator('label:text-is("V1")').first.locator("xpath=following::input[1]")
            for k in range(5):
                box.fill(f"{0.8 + 0.01 * k:.2f}")
                page.evaluate("() => { window.__times = []; }")
                t0 = page.evaluate("() => performance.now()")
                box.press("Enter")
                time.sleep(1.5)
                times = page.evaluate("() => window.__times")
                burst = [t for t in times if t >= t0]
                end = burst[0] if burst else t0
                for t in burst[1:]:
                    if t - end > 60.0:
                        break
                    end = t
                redraws.append(end - t0)
            return {
                "bytes_first_picture": float(first_bytes),
                "fps": (f1 - f0) / seconds,
                "animation_frames_per_s": (k1 - k0) / seconds,
                "messages_per_s": (m1 - m0) / seconds,
                "slider_to_redraw_ms": statistics.median(redraws),
                "smallest_text_px": smallest,
            }
        finally:
            browser.close()


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--width", type=int, default=1280)
    parser.add_argument("--height", type=int, default=720)
    parser.add_argument("--seconds", type=float, default=5.0)
    parser.add_argument("--theme", choices=("light", "dark"), default="light", help="the tab's theme")
    parser.add_argument("--presenter", action="store_true", help="play in presenter mode (key F)")
    parser.add_argument("--warm", type=float, default=2.0, help="seconds of playback before counting")
    parser.add_argument("--pairs", type=int, default=0, help="alternate with a bare viser page N times")
    args = parser.parse_args()
    if not args.pairs:
        r = measure(args.width, args.height, args.seconds, args.theme, args.presenter, args.warm)
        print(" ".join(f"{k}={v:.1f}" for k, v in r.items()), flush=True)
        return
    app_fps, bare_fps = [], []
    for k in range(args.pairs):
        bare = measure_bare(16, args.width, args.height, args.seconds, moving=True)
        app = measure(args.width, args.height, args.seconds, args.theme, args.presenter, args.warm)
        bare_fps.append(bare["fps"])
        app_fps.append(app["fps"])
        print(f"pair {k + 1}: bare_fps={bare['fps']:.1f} app_fps={app['fps']:.1f}", flush=True)
    b, a = statistics.median(bare_fps), statistics.median(app_fps)
    print(f"{args.width}x{args.height} median bare_fps={b:.1f} app_fps={a:.1f} ratio={a / b:.2f}", flush=True)


if __name__ == "__main__":
    main()
