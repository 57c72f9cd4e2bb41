"""MkDocs hook: the repository's pictures in ``assets/`` become the site's ``assets/``.

The README and the docs show the same pictures, made by ``python -m tests.make_assets`` and the
figure and benchmark commands; they live once, at the top of the repository. This hook adds them
to the site as they are (images and the benchmark's JSON table; not the benchmark's HTML charts,
which load plotly.js from a CDN), so a page links them as ``assets/...`` from the docs' root.
"""

from __future__ import annotations

from pathlib import Path

from mkdocs.config.defaults import MkDocsConfig
from mkdocs.structure.files import File, Files

#: The kinds of file the site takes from ``assets/``.
SHOWN = frozenset({".png", ".gif", ".svg", ".json", ".txt"})


def on_files(files: Files, config: MkDocsConfig) -> Files:
    assets = Path(config.config_file_path).parent / "assets"
    for path in sorted(assets.rglob("*")):
        if path.is_file() and path.suffix in SHOWN:
            uri = path.relative_to(assets.parent).as_posix()
            files.append(File.generated(config, uri, abs_src_path=str(path)))
    return files
