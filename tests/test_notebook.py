"""The README's notebook example, run outside a notebook."""

from __future__ import annotations

import re
from pathlib import Path

import plotly.graph_objects as go

README = Path(__file__).resolve().parents[1] / "README.md"


def notebook_block() -> str:
    text = README.read_text()
    m = re.search(r"<!-- notebook-example[^>]*-->\s*```python\n(.*?)```", text, re.S)
    assert m, "README has no notebook example"
    return m.group(1)


def test_readme_notebook_example_runs() -> None:
    namespace: dict[str, object] = {}
    exec(compile(notebook_block(), "README.md", "exec"), namespace)
    fig = namespace["fig"]
    rec = namespace["rec"]
    assert isinstance(fig, go.Figure)
    texts = [a.text for a in fig.layout.annotations]
    assert any("T<sub>1</sub>" in t for t in texts) and any("T'<sub>2</sub>" in t for t in texts)
    html = rec._repr_html_()  # type: ignore[attr-defined]
    assert html.startswith("<iframe srcdoc=") and "__VISER_EMBED_DATA__" in html
    assert len(html) > 100_000
