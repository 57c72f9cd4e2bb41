"""A Minkowski diagram in a notebook: one call, an interactive plotly figure, every curve exact.

In Jupyter the last line of a cell shows the figure; here it is written to an HTML file
(plotly.js inlined, so it opens offline) and its traces are listed.
"""

import sys
import tempfile
from pathlib import Path

import rigidrel_core as rr
from rigidrel_app.notebook import diagram


def main() -> None:
    scene = rr.build_scene("wall-collision", v=0.8, eps=0.5)  # a half-elastic bounce at V = 0.8
    frame = scene.frame("rod before")  # the rod at rest; the wall comes at it
    fig = diagram(scene, frame)
    names = sorted({str(t["name"]) for t in fig.to_dict()["data"] if t.get("showlegend")})
    print(f"{scene.kind} in the {frame.name} frame (beta = {frame.beta:+.4f}): traces {', '.join(names)}")
    out = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(tempfile.mkdtemp(prefix="rigidrel-")) / "diagram.html"
    fig.write_html(out, include_plotlyjs=True)
    print(f"written {out}")


if __name__ == "__main__":
    main()
