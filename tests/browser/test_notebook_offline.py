"""A real notebook, run headless by a Jupyter kernel (nbclient), then its outputs opened in Chromium
with the network cut: the diagrams draw (plotly.js from the installed package, never a CDN)."""

from __future__ import annotations

import os
import re
import socket
import subprocess
import sys
import urllib.request
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from rigidrel_app.notebook.live_state import figure_arrays, live_figure, start
from tests.browser.test_accessibility_browser import serious_violations
from tests.viser_client import wait_until

pytestmark = pytest.mark.slow  # a Jupyter kernel runs the notebook; the tests that open it in Chromium are browser too

CELLS = [
    "import rigidrel_core as rr\nfrom rigidrel_app.notebook import diagram, lesson",
    'scene = rr.build_scene("wall-collision", eps=0.0)\ndiagram(scene, scene.frame("rod before"))',
    'diagram(rr.build_scene("rod-collision", mass2=2.0), rr.LAB)',
    'lesson("paper")',
    # the live view: built in the kernel, then one slider moved there (as a person's drag arrives)
    'from rigidrel_app.notebook import explore\nview = explore("rod-collision", v1=0.6, frame="barycentric")\nview',
    "from rigidrel_app.notebook.live_state import figure_arrays, live_figure, start\n"
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
    import nbformat  # imported here: nbformat takes seconds to import, and the fast lane collects this file
    from nbclient import NotebookClient

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
    anys = [m for m in state.values() if m["model_name"] == "AnyModel"]  # the figure, and the sliders' names
    figure = max(anys, key=lambda m: len(m["state"]["_esm"]))
    assert len(anys) == 2 and any("aria-label" in m["state"]["_esm"] for m in anys)
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
def test_the_saved_outputs_draw_offline_and_are_axe_clean(browser: Any, executed: Any, tmp_path: Path) -> None:
    """The outputs as a saved notebook's page shows them (a page with a title and a language, as
    nbconvert writes): they draw with the network cut, and axe-core finds no serious violation in them."""
    page_file = tmp_path / "outputs.html"
    head = "<!DOCTYPE html><html lang='en'><meta charset='utf-8'><title>A notebook's outputs</title>"
    page_file.write_text(head + "\n".join(_html_outputs(executed)), encoding="utf-8")
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
        wait_until(lambda: page.locator(".js-plotly-plot .main-svg").count() >= expected, timeout=180)
        assert requests == [] and errors == [], (requests, errors)
        assert serious_violations(page) == []
    finally:
        context.close()


# ---------------------------------------------------------------------------------- the live view in JupyterLab
# The live view needs a kernel (the core runs there), so it is opened where a person uses it: a
# JupyterLab served on 127.0.0.1, with every request to anywhere else refused. Its scripts (the
# widget manager, anywidget, plotly's FigureWidget bundle) come from the installed packages.

LIVE_CELL = 'from rigidrel_app.notebook import explore\nexplore("rod-collision", v1=0.6, frame="barycentric", t=0.3)'


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


@pytest.fixture
def jupyterlab(tmp_path: Path) -> Iterator[str]:
    """A JupyterLab on 127.0.0.1 (no token: only this machine reaches it) serving ``live.ipynb``."""
    import nbformat

    nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(LIVE_CELL)])
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
    nbformat.write(nb, tmp_path / "live.ipynb")
    port = _free_port()
    home = tmp_path / "home"  # its settings and workspaces, not the user's
    env = {**os.environ, "JUPYTER_CONFIG_DIR": str(home / "config"), "JUPYTERLAB_WORKSPACES_DIR": str(home / "ws")}
    env["JUPYTER_RUNTIME_DIR"] = str(home / "runtime")
    args = [
        sys.executable, "-m", "jupyterlab", "--no-browser", f"--ServerApp.port={port}", "--ServerApp.port_retries=0",
        "--ServerApp.ip=127.0.0.1", "--IdentityProvider.token=", "--ServerApp.password=",
        f"--ServerApp.root_dir={tmp_path}", "--LabApp.news_url=None",
        "--LabApp.check_for_updates_class=jupyterlab.NeverCheckForUpdate", "--LabApp.extension_manager=readonly",
        "--ServerApp.terminals_enabled=False", "--allow-root",  # root in CI containers
    ]  # fmt: skip
    log = (tmp_path / "jupyterlab.log").open("w")
    server = subprocess.Popen(args, env=env, stdout=log, stderr=subprocess.STDOUT, cwd=tmp_path)
    url = f"http://127.0.0.1:{port}"

    def up() -> bool:
        if server.poll() is not None:
            raise AssertionError((tmp_path / "jupyterlab.log").read_text())
        try:
            with urllib.request.urlopen(f"{url}/api/status", timeout=5) as r:
                return r.status == 200
        except OSError:
            return False

    try:
        wait_until(up, timeout=120, interval=0.5)
        yield url
    finally:
        server.terminate()
        try:
            server.wait(timeout=30)
        except subprocess.TimeoutExpired:
            server.kill()
            server.wait()
        log.close()


def _plot_arrays(page: Any) -> list[list[float | None]]:
    """Every trace's x in the page's plotly figure (NaN comes back as None)."""
    return page.evaluate("() => document.querySelector('.js-plotly-plot').data.map(t => Array.from(t.x))")


def _set_slider(page: Any, label: str, value: str) -> None:
    """Type ``value`` into the readout box of the slider labelled ``label`` (as a person does)."""
    slider = page.locator(".widget-slider", has=page.locator(".widget-label", has_text=label)).first
    box = slider.locator(".widget-readout")
    box.click()
    page.keyboard.press("Control+A")
    page.keyboard.type(value)
    page.keyboard.press("Enter")


@pytest.mark.browser
def test_the_live_view_in_jupyterlab_offline(browser: Any, jupyterlab: str, shots: Path) -> None:
    context = browser.new_context(viewport={"width": 1280, "height": 720})
    elsewhere: list[str] = []
    errors: list[str] = []
    mine = re.compile(rf"^(https?|wss?)://127\.0\.0\.1:{jupyterlab.rsplit(':', 1)[1]}/")
    context.on(
        "request",
        lambda r: None if mine.match(r.url) or r.url.startswith(("data:", "blob:")) else elsewhere.append(r.url),
    )
    context.route(
        re.compile(r"^(https?|wss?)://"),
        lambda route: route.continue_() if mine.match(route.request.url) else route.abort(),
    )
    page = context.new_page()
    page.on("pageerror", lambda e: errors.append(str(e)))
    page.on("console", lambda m: errors.append(f"console: {m.text}") if m.type == "error" else None)
    try:
        page.goto(f"{jupyterlab}/lab/tree/live.ipynb", timeout=180_000)
        cell = page.locator(".jp-Cell .cm-content").first
        cell.wait_for(timeout=180_000)
        # the kernel is ready when the status bar says so; a cell run before that is lost
        status = page.locator(".jp-StatusBar-Widget", has_text="| Idle").first
        status.wait_for(timeout=180_000)
        no_news = page.get_by_role("button", name="No", exact=True)  # JupyterLab asks whether to fetch news
        if no_news.count():
            no_news.first.click()
        cell.click()
        page.keyboard.press("Shift+Enter")
        page.locator(".jp-InputPrompt", has_text="[1]").first.wait_for(timeout=180_000)
        plot = page.locator(".jp-OutputArea .js-plotly-plot .main-svg").first
        plot.wait_for(timeout=180_000)
        wait_until(lambda: "V1 = 0.6" in page.locator(".jp-OutputArea").first.inner_text(), timeout=180)
        page.screenshot(path=str(shots / "live-1280x720.png"))
        assert serious_violations(page, within=".jp-OutputArea-output") == []  # the view, not JupyterLab's own page
        before = _plot_arrays(page)

        _set_slider(page, "V1", "0.8")
        wait_until(lambda: "V1 = 0.8" in page.locator(".jp-OutputArea").first.inner_text(), timeout=180)
        wait_until(lambda: _plot_arrays(page) != before, timeout=180)
        expected = figure_arrays(live_figure(start("rod-collision", "barycentric", 0.3, v1=0.8)))
        shown = _plot_arrays(page)
        assert len(shown) == len(expected)
        for k, (drawn, (x, _)) in enumerate(zip(shown, expected)):
            got = np.array([np.nan if v is None else v for v in drawn], dtype=float)
            assert np.array_equal(got, x, equal_nan=True), (k, got[:5], x[:5], got.size, x.size)
        page.set_viewport_size({"width": 1920, "height": 1080})
        page.screenshot(path=str(shots / "live-v1-0.8-1920x1080.png"))

        _set_slider(page, "V1", "0")  # the rods (V2 = 0) would never meet: refused, the picture stays
        wait_until(lambda: "refused" in page.locator(".jp-OutputArea").first.inner_text(), timeout=180)
        assert "v2 must be less than v1" in page.locator(".jp-OutputArea").first.inner_text()
        assert _plot_arrays(page) == shown
        page.screenshot(path=str(shots / "live-refused-1920x1080.png"))
        assert serious_violations(page, within=".jp-OutputArea-output") == []  # with its notice
        assert elsewhere == [] and errors == [], (elsewhere, errors)
    except Exception:
        page.screenshot(path=str(shots / "failure.png"))
        raise AssertionError(f"requests elsewhere: {elsewhere}; page errors: {errors}")  # noqa: B904 (the cause chains)
    finally:
        context.close()
