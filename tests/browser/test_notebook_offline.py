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
]


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


def test_outputs_carry_plotly_once_and_name_no_cdn(executed: Any) -> None:
    outputs = _html_outputs(executed)
    assert len(outputs) == 3  # two diagrams and the lesson
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
