"""The app's examples (examples/02_export/, examples/03_notebook/) run as scripts and write what they say."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
from PIL import Image

ROOT = Path(__file__).resolve().parents[1]
pytestmark = pytest.mark.slow


def run(example: str, *args: str) -> str:
    r = subprocess.run(
        [sys.executable, str(ROOT / "examples" / example), *args], capture_output=True, text=True, timeout=300
    )
    assert r.returncode == 0, r.stderr
    return r.stdout


def test_export_example_writes_offline_pages_and_a_gif(tmp_path: Path) -> None:
    out = run("02_export/01_offline_pages.py", str(tmp_path))
    names = sorted(p.name for p in tmp_path.iterdir())
    assert names == ["fig4-3d.html", "fig4-diagram.html", "fig4-lanes.gif"]
    assert "__VISER_EMBED_DATA__" in (tmp_path / "fig4-3d.html").read_text()
    page = (tmp_path / "fig4-diagram.html").read_text()
    assert "barycentric (\\u03b2 = 0.4286)" in page  # Fig. 4's barycentric frame: u = 1.5/3.5 (JSON-escaped β)
    assert int(getattr(Image.open(tmp_path / "fig4-lanes.gif"), "n_frames", 1)) == 60
    assert out.count(" MB") == 3


def test_notebook_example_draws_the_wall_and_writes_an_offline_page(tmp_path: Path) -> None:
    out = run("03_notebook/01_diagram.py", str(tmp_path / "d.html"))
    assert "in the rod before frame (beta = -0.8000)" in out and "wall" in out
    html = (tmp_path / "d.html").read_text()
    assert '<script src="https://cdn.plot.ly' not in html and len(html) > 1_000_000  # plotly.js inlined
