"""A real notebook, run headless by a Jupyter kernel (nbclient), then its outputs opened in Chromium
with the network cut: the diagrams draw (plotly.js from the installed package, never a CDN)."""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

import nbformat
import pytest
from nbclient import NotebookClient

from tests.viser_client import wait_until

CELLS = [
    "import rigidrel_core as rr\nfrom rigidrel_app.notebook import diagram, lesson",
    'scene = rr.build_scene("wall-collision", eps=0.0)\ndiagram(scene, scene.frame("rod before"))',
    'diagram(rr.build_scene("rod-collision", m2=2.0), rr.LAB)',
    'lesson("paper")',
    # the live view: built in the kernel, then one slider moved there (as a person's drag arrives)
    'from rigidrel_app.notebook import explore\nview = explore("rod-collision", v1=0.6, frame="barycentric")\nview',
    "from rigidrel_app.notebook.explore import figure_arrays, live_figure, start\n"
    "import numpy as np\n"
    "before = [np.asarray(t.x, dtype=float) for t in view.figure.data]\n"
    'view.sliders["v1"].value = 0.8\n'
    'expected = figure_arrays(live_figure(start("rod-collision", "barycentric", view.state.now, v1=0.8)))\n'
    "after = [(np.asarray(t.x, dtype=float), np.asarray(t.y, dtype=float)) for t in view.figure.data]\n"
    "same = len(after) == len(expected) and all(np.array_equal(a[0], e[0], equal_nan=True) and "
    "np.array_equal(a[1], e[1], equal_nan=True) for a, e in zip(after, expected))\n"
    "moved = len(before) != len(after) or any(not np.array_equal(b, a[0], equal_nan=True) "
    "for b, a in zip(before, after))\n"
    'print("live view:", view.state.settings.value("v1"), same, moved, repr(view.state.notice))',
]
#: The cells before the live view's (their HTML outputs are the static diagrams and the lesson).
STATIC_CELLS = 4


@pytest.fixture(scope="module")
def executed(tmp_path_factory: pytest.TempPathFactory) -> Any:
    nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(c) for c in CELLS])
    # no proxy, no route: a kernel that reached for the network would fail, not hang
    NotebookClient(
        nb, timeout=300, kernel_name="python3", resources={"metadata": {"path": str(tmp_path_factory.mktemp("nb"))}}
    ).execute()
    return nb


def _html_outputs(nb: Any) -> list[str]:
    return [o["data"]["text/html"] for c in nb.cells for o in c.get("outputs", []) if "text/html" in o.get("data", {})]


def test_the_live_view_redraws_in_the_kernel(executed: Any) -> None:
    """The view is a widget (no HTML of its own); the slider moved in the kernel redrew its figure
    exactly as the core's scene with the new value, and the notebook keeps the widgets' state."""
    view_cell, drive_cell = executed.cells[STATIC_CELLS], executed.cells[STATIC_CELLS + 1]
    bundle = view_cell.outputs[0]["data"]
    assert "application/vnd.jupyter.widget-view+json" in bundle and "text/html" not in bundle
    printed = "".join(o.get("text", "") for o in drive_cell.outputs)
    assert printed.strip() == "live view: 0.8 True True ''", drive_cell.outputs
    state = executed.metadata["widgets"]["application/vnd.jupyter.widget-state+json"]["state"]
    models = {m["model_name"] for m in state.values()}
    assert {"FloatSliderModel", "FloatLogSliderModel", "DropdownModel", "AnyModel"} <= models, models
    # the FigureWidget's script is plotly's own bundle, carried by the kernel, not fetched from a CDN
    (figure,) = [m for m in state.values() if m["model_name"] == "AnyModel"]
    esm = figure["state"]["_esm"]
    assert len(esm) > 1_000_000 and not re.search(r"""^\s*import\s[^;]*["']https?://""", esm, re.M)


def test_outputs_carry_plotly_once_and_name_no_cdn(executed: Any) -> None:
    outputs = _html_outputs(executed)
    assert len(outputs) == 3  # two diagrams and the lesson (the live view is a widget)
    assert not any(re.search(r"<script[^>]*\bsrc=", o) for o in outputs)  # no script loaded from anywhere
    with_plotly = [o for o in outputs if "plotly.js v" in o or "Plotly=" in o or len(o) > 3_000_000]
    assert len(with_plotly) == 1 and outputs[0] is with_plotly[0]  # only the first carries plotly.js
    assert "Riding the rod" in outputs[2] and "V′2 = 0.4382" in outputs[2]


@pytest.mark.browser
def test_the_saved_outputs_draw_offline(browser: Any, executed: Any, tmp_path: Path) -> None:
    page_file = tmp_path / "outputs.html"
    page_file.write_text("<!DOCTYPE html><meta charset='utf-8'>" + "\n".join(_html_outputs(executed)), encoding="utf-8")
    context = browser.new_context(viewport={"width": 1280, "height": 900})
    requests: list[str] = []
    errors: list[str] = []
    context.on(
        "request", lambda r: None if r.url.startswith(("file:", "data:", "blob:", "about:")) else requests.append(r.url)
    )
    context.route(re.compile(r"^(https?|wss?)://"), lambda route: route.abort())
    try:
        page = context.new_page()
        page.on("pageerror", lambda e: errors.append(str(e)))
        page.goto(page_file.as_uri(), timeout=120_000)
        expected = 2 + len(re.findall("<h3>", _html_outputs(executed)[2]))
        wait_until(lambda: page.locator(".js-plotly-plot .main-svg").count() >= expected, timeout=120)
        assert requests == [] and errors == [], (requests, errors)
    finally:
        context.close()
