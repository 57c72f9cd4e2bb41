"""``rigidrel export --lesson``: a lesson as a folder of static pages, for any web host, an LMS, or
opened straight from disk. Nothing in it asks the network for anything.

    DIR/index.html            the lesson's title and its steps
    DIR/step-01.html          the caption over the canvas playing (one 1280x720 screen), then the
                              interactive diagram, the picture in words and prev/next
    DIR/step-01-canvas.html   the live app's canvas (lanes, diagrams, legend), seen straight on at
                              its text sizes (a viser recording; plays by itself)
    DIR/step-01-diagram.html  the diagram with its sliders
    DIR/plotly.min.js         one copy, shared by every diagram page

A step page is laid out as the live app shows a lesson: a caption band over the canvas, the band
as high as the window leaves above a canvas of :data:`CANVAS_HEIGHT` (at most a quarter of the
window; a longer caption scrolls in it), the canvas scaled whole to the rest (at 1280x720, one page
px one CSS px: the live app's text sizes).

Keys on a step page: → / PageDown / Space next, ← / PageUp previous, Home the index (a clicker
sends PageUp/PageDown), also with the focus inside its lanes or its diagram (after a click there;
a control there with the focus keeps the arrows and Space). A step page embeds in slides or a Jupyter Book as an iframe
(``docs/lessons.md`` has the snippets).
"""

from __future__ import annotations

import html
import json
import shutil
from collections.abc import Callable
from pathlib import Path

import plotly

from ..lessons import Lesson, Step
from ..lessons.tour import caption_body_html
from ..view.describe import describe
from ..view.layout import CAPTION_SHARE, NORMAL, caption_reserve
from ..view.scene_view import CLOCK_RULE
from ..view.state import settings_for
from ..view.vocabulary import Shade, names_html
from .diagram_html import diagram_html
from .recording import record_canvas_html

#: The canvas a step records (CSS px): the live app's at 1280 wide, as high as a lesson's caption
#: band leaves it (two lanes and diagrams of 150 px).
CANVAS_WIDTH = 1280
CANVAS_HEIGHT = caption_reserve(NORMAL)

_STYLE = """
body { font-family: system-ui, -apple-system, "Segoe UI", Roboto, sans-serif; margin: 0; color: #222;
       font-size: 20px; line-height: 1.45; background: #fff; }
header { display: flex; align-items: baseline; gap: 1em; padding: 0.6em 1em; background: #0072B2; color: #fff; }
header a { color: #fff; }
header .count { margin-left: auto; font-variant-numeric: tabular-nums; }
main { padding: 0.5em 1em 1em; }
h1 { font-size: 1.5em; margin: 0.2em 0 0.3em; }
.caption { max-width: 60em; }
.band { box-sizing: border-box; height: var(--band); overflow-y: auto; border-bottom: 3px solid #0072B2; }
.band header { padding: 0.2em 1em; font-size: 0.8em; }
.band h1 { font-size: 1.2em; margin: 0.2em 1rem 0.1em; }
.band .caption { margin: 0 1rem 0.3em; }
.band .caption p { margin: 0.2em 0; }
.views { display: flex; flex-direction: column; gap: 0.8em; margin-top: 0.6em; }
.views iframe { border: 1px solid #ccc; }
iframe.diagram { width: 1270px; max-width: 100%; height: 730px; }
nav.steps { display: flex; justify-content: space-between; margin-top: 0.8em; font-size: 1.1em; }
nav a { padding: 0.3em 0.8em; border: 1px solid #0072B2; border-radius: 0.3em; text-decoration: none; color: #0072B2; }
ol.index li { margin: 0.3em 0; }
.note { color: #555; font-size: 0.85em; }
"""
#: A step page's band and canvas, as the live app lays out a lesson (``live/assets/caption.js``):
#: the band what the window leaves above the canvas, at least 88 px and at most CAPTION_SHARE of
#: it; the canvas the recorded size, zoomed whole to the rest by :data:`_FIT_CANVAS`.
_STEP_STYLE = f"""
.step {{ --band: max(88px, min({100 * CAPTION_SHARE:g}vh, calc(100vh - {CANVAS_HEIGHT}px))); }}
iframe.canvas {{ display: block; border: 0; margin: 0 auto; width: {CANVAS_WIDTH}px; height: {CANVAS_HEIGHT}px; }}
"""

#: The canvas zoomed to the width and the height the band leaves, text and all (CSS ``zoom``: the
#: recorded page keeps its layout and draws at the finer resolution). Its labels are sized on the
#: screen, not the page: scaling the frame any other way would move them apart from their marks.
_FIT_CANVAS = f"""
(function () {{
  var canvas = document.querySelector("iframe.canvas"), band = document.querySelector(".band");
  if (!canvas || !band) return;
  function fit() {{
    var room = window.innerHeight - band.getBoundingClientRect().height;
    var k = Math.min(document.documentElement.clientWidth / {CANVAS_WIDTH}, room / {CANVAS_HEIGHT});
    canvas.style.zoom = String(Math.max(0.25, k));
  }}
  window.addEventListener("resize", fit);
  fit();
}})();
"""

#: The pages' dark theme (``--theme dark``): light text on black, the live app's colours.
_DARK_STYLE = """
body { color: #DDDDDD; background: #000000; }
header { background: #17150A; color: #F2F2F2; border-bottom: 3px solid #4DBFFF; }
header a { color: #F2F2F2; }
.views iframe { border-color: #333333; }
nav a { border-color: #4DBFFF; color: #4DBFFF; }
a { color: #4DBFFF; }
.note { color: #AAAAAA; }
"""

_KEYS = """
function rigidrelGo(key) {
  var go = null;
  if (key === "ArrowRight" || key === "PageDown" || key === " ") go = NEXT;
  else if (key === "ArrowLeft" || key === "PageUp") go = PREV;
  else if (key === "Home") go = "index.html";
  if (go) window.location.href = go;
  return go !== null;
}
document.addEventListener("keydown", function (e) {
  if (e.altKey || e.ctrlKey || e.metaKey) return;
  if (rigidrelGo(e.key)) e.preventDefault();
});
// a key pressed while the focus is inside one of the step's frames (the lanes, the diagram)
window.addEventListener("message", function (e) {
  var ours = Array.prototype.some.call(document.querySelectorAll("iframe"), function (f) {
    return f.contentWindow === e.source;
  });
  if (ours && e.data && typeof e.data.rigidrelKey === "string") rigidrelGo(e.data.rigidrelKey);
});
"""

#: Put into a step's lanes and diagram pages: a lesson's keys pressed inside the frame reach the step
#: page around it. The clicker's PageUp, PageDown and Home always; the arrows and Space unless a
#: control inside the frame has the focus (a slider's handle, a box, a button keep their keys).
FRAME_KEYS = """<script>
if (window.parent !== window) document.addEventListener("keydown", function (e) {
  if (e.altKey || e.ctrlKey || e.metaKey || e.defaultPrevented) return;
  var t = e.target;
  var own = t && t.closest && t.closest("input, select, textarea, button, [role=slider], [contenteditable]");
  var clicker = e.key === "PageDown" || e.key === "PageUp" || e.key === "Home";
  var page = e.key === "ArrowRight" || e.key === "ArrowLeft" || e.key === " ";
  if (clicker || (page && !own)) { e.preventDefault(); window.parent.postMessage({ rigidrelKey: e.key }, "*"); }
});
</script>"""


def with_frame_keys(page: str) -> str:
    """``page`` (an exported lanes or diagram page) passing a lesson's keys on to the page it is
    framed in (:data:`FRAME_KEYS`)."""
    return page.replace("</body>", FRAME_KEYS + "</body>", 1)


#: Under the lanes: what their clocks read (each end's proper time, and where it is zero).
CLOCKS_NOTE = (
    f"The clocks on the rods' ends in the lanes read each end's proper time τ: {CLOCK_RULE} (so two ends, "
    "or two bodies on the same worldline, can read differently at one instant)."
)


def step_name(k: int) -> str:
    """``step-01`` for the first step."""
    return f"step-{k + 1:02d}"


def _page(
    title: str, body: str, next_href: str | None, prev_href: str | None, shade: Shade = "light", script: str = ""
) -> str:
    script = f"var NEXT = {json.dumps(next_href)}, PREV = {json.dumps(prev_href)};\n{_KEYS}{script}"
    style = _STYLE + _STEP_STYLE + (_DARK_STYLE if shade == "dark" else "")
    return (
        "<!DOCTYPE html>\n<html lang='en'><head><meta charset='utf-8'>"
        "<meta name='viewport' content='width=device-width, initial-scale=1'>"
        f"<title>{html.escape(title)}</title><style>{style}</style></head>"
        f"<body>{body}<script>{script}</script></body></html>\n"
    )


def _in_words(step: Step) -> str:
    """The step's picture in words (what the live app's screen reader hears, key D), at the time it
    opens on (its start, else the origin event's t = 0 when its window holds it); its event names
    written as the canvas and the caption write them (T<sub>1</sub>, T′<sub>1</sub>)."""
    window = step.window or step.resolved.scene.time_window(frame=step.resolved.frame)
    start = step.start if step.start is not None else min(max(0.0, window[0]), window[1])
    lines = "".join(
        f"<p>{names_html(html.escape(line, quote=False))}</p>"
        for line in describe(step.resolved, start, one_lane=False).full.splitlines()
    )
    return f"<details class='words'><summary>The picture in words</summary>{lines}</details>"


def _step_page(lesson: Lesson, k: int, step: Step, shade: Shade = "light") -> str:
    n = len(lesson.steps)
    prev_href = f"{step_name(k - 1)}.html" if k > 0 else "index.html"
    next_href = f"{step_name(k + 1)}.html" if k + 1 < n else None
    name = step_name(k)
    nav = f"<a href='{prev_href}' rel='prev'>← {'previous' if k > 0 else 'contents'}</a>"
    nav += f"<a href='{next_href}' rel='next'>next →</a>" if next_href else "<span></span>"
    ride = ""
    if step.ride is not None:
        ride = (
            "<p class='note'>The canvas above rides a point of the rod, as the live app does; the "
            f"diagram with sliders shows the step in {html.escape(step.resolved.frame.label())}.</p>"
        )
    # the band (a region of its own, which the keys scroll when the caption is longer) over the
    # canvas, as in the live app; under them the interactive diagram, the words and the way on
    body = (
        "<div class='step'><div class='band' tabindex='0' role='region' aria-label='Step caption'>"
        f"<header><a href='index.html'>{html.escape(lesson.title)}</a>"
        f"<span class='count'>step {k + 1} of {n}</span></header>"
        f"<h1>{html.escape(step.title)}</h1><div class='caption'>{caption_body_html(step.caption)}</div></div>"
        f"<iframe class='canvas' src='{name}-canvas.html' "
        "title='the rods and their Minkowski diagrams, in the lab and in the chosen frame'></iframe></div><main>"
        f"<div class='views'><iframe class='diagram' src='{name}-diagram.html' "
        f"title='Minkowski diagram with sliders'></iframe></div>{ride}"
        f"<p class='note'>{html.escape(CLOCKS_NOTE)}</p>{_in_words(step)}<nav class='steps'>{nav}</nav></main>"
    )
    title = f"{step.title} · {lesson.title}"
    return _page(title, body, next_href, prev_href if k > 0 else "index.html", shade, _FIT_CANVAS)


def _index_page(lesson: Lesson, shade: Shade = "light") -> str:
    items = "".join(
        f"<li><a href='{step_name(k)}.html'>{html.escape(s.title)}</a></li>" for k, s in enumerate(lesson.steps)
    )
    subtitle = f"<p>{html.escape(lesson.subtitle)}</p>" if lesson.subtitle else ""
    body = (
        f"<header><span>{html.escape(lesson.title)}</span><span class='count'>{len(lesson.steps)} steps</span></header>"
        f"<main><h1>{html.escape(lesson.title)}</h1>{subtitle}<ol class='index'>{items}</ol>"
        "<p class='note'>Keys: → or PageDown next, ← or PageUp previous, Home here.</p></main>"
    )
    return _page(lesson.title, body, f"{step_name(0)}.html", None, shade)


def export_lesson(
    lesson: Lesson,
    out: Path,
    seconds: float = 10.0,
    fps: float = 30.0,
    progress: Callable[[Path], None] | None = None,
    shade: Shade = "light",
) -> list[Path]:
    """Write the lesson's pages into ``out`` (created if missing), on a ``shade`` ground (dark: the
    live app's dark theme in every page, lanes and diagram); returns the files written."""
    out.mkdir(parents=True, exist_ok=True)
    written: list[Path] = []

    def write(path: Path, text: str) -> None:
        path.write_text(text, encoding="utf-8")
        written.append(path)
        if progress is not None:
            progress(path)

    plotly_js = Path(plotly.__file__).parent / "package_data" / "plotly.min.js"
    shutil.copyfile(plotly_js, out / "plotly.min.js")
    written.append(out / "plotly.min.js")
    write(out / "index.html", _index_page(lesson, shade))
    for k, step in enumerate(lesson.steps):
        name = step_name(k)
        resolved = step.resolved
        settings = settings_for(resolved.scene, resolved.frame).with_layers(step.layers)
        canvas = record_canvas_html(resolved, step.scenario.settings, CANVAS_WIDTH, CANVAS_HEIGHT, seconds, fps, shade)
        write(out / f"{name}-canvas.html", with_frame_keys(canvas))
        write(out / f"{name}-diagram.html", with_frame_keys(diagram_html(settings, "beside", shade)))
        write(out / f"{name}.html", _step_page(lesson, k, step, shade))
    return written
