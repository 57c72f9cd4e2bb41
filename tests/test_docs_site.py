"""The docs site builds with warnings as errors, and no link of it or of the README is broken.

The slow test builds the site (``mkdocs build --strict``, as ``mkdocs.yml`` asks) into a temporary
folder and follows every internal link and anchor of the built HTML; the site must also load
nothing from the network. The fast tests hold the README to a front page (at most
:data:`README_MAX_LINES` lines) whose relative links and pictures are files of the repository, keep
the architecture page's list of layers the one import-linter enforces, run the Python examples of
the README and the pages (those that need no server, browser or kernel), and check that the link
checker itself finds a broken link and a missing anchor.
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
import tomllib
from html.parser import HTMLParser
from pathlib import Path
from urllib.parse import unquote, urlsplit

import pytest

ROOT = Path(__file__).resolve().parents[1]
README = ROOT / "README.md"
#: The README is a front page: what rigidrel is, pictures, the two commands, a few command lines, links.
README_MAX_LINES = 150
#: Links that leave the site (or the repository): not followed.
EXTERNAL = re.compile(r"^(?:[a-z][a-z0-9+.-]*:|//)", re.I)


class _Page(HTMLParser):
    """One HTML page's ids and the links it follows: ``href`` of ``a`` and ``link``, ``src`` of
    ``img``, ``script``, ``iframe`` and ``source``."""

    def __init__(self) -> None:
        super().__init__(convert_charrefs=True)
        self.ids: set[str] = set()
        self.links: list[tuple[str, str]] = []

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        a = {k: v for k, v in attrs if v is not None}
        if "id" in a:
            self.ids.add(a["id"])
        if tag == "a" and "name" in a:
            self.ids.add(a["name"])
        attr = {"a": "href", "link": "href", "img": "src", "script": "src", "iframe": "src", "source": "src"}.get(tag)
        if attr is not None and attr in a:
            self.links.append((tag, a[attr]))


def _parse(path: Path) -> _Page:
    page = _Page()
    page.feed(path.read_text(encoding="utf-8"))
    return page


def broken_links(site: Path) -> list[str]:
    """Every internal link of the HTML pages under ``site`` whose file is missing, or whose anchor
    is no id of its page; and every resource a page would load from the network."""
    pages = {p.resolve(): _parse(p) for p in sorted(site.rglob("*.html"))}
    problems: list[str] = []
    for path, page in pages.items():
        name = path.relative_to(site.resolve())
        for tag, link in page.links:
            if EXTERNAL.match(link):
                if tag in ("img", "script", "iframe", "source") or (tag == "link" and not link.startswith("mailto:")):
                    problems.append(f"{name}: <{tag}> loads {link} from the network")
                continue
            parts = urlsplit(link)
            if not parts.path:
                target = path
            elif parts.path.startswith("/"):  # from the site's root (the 404 page's links)
                target = (site / unquote(parts.path).lstrip("/")).resolve()
            else:
                target = (path.parent / unquote(parts.path)).resolve()
            if target.is_dir():
                target = target / "index.html"
            if not target.is_file():
                problems.append(f"{name}: {link} (no file {target})")
                continue
            anchor = unquote(parts.fragment)
            if anchor and target.suffix == ".html":
                ids = pages[target].ids if target in pages else _parse(target).ids
                if anchor not in ids:
                    problems.append(f"{name}: {link} (no anchor #{anchor} in {target.name})")
    return problems


def readme_targets() -> list[str]:
    """The README's relative links and pictures (Markdown and HTML), without their anchors."""
    text = README.read_text(encoding="utf-8")
    found = re.findall(r"!?\[[^\]]*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)", text)
    found += re.findall(r"""<(?:img|a)\b[^>]*?(?:src|href)=["']([^"']+)["']""", text)
    return [t for t in found if not EXTERNAL.match(t) and not t.startswith("#")]


def test_the_readme_is_a_front_page() -> None:
    lines = README.read_text(encoding="utf-8").splitlines()
    assert len(lines) <= README_MAX_LINES, f"README.md: {len(lines)} lines; a front page has {README_MAX_LINES} at most"


def test_the_readmes_links_and_pictures_are_files() -> None:
    targets = readme_targets()
    assert any(t.startswith("assets/") for t in targets) and any(t.startswith("docs/") for t in targets)
    missing = [t for t in targets if not (ROOT / unquote(urlsplit(t).path)).exists()]
    assert not missing, f"README.md links to files that do not exist: {missing}"


def test_the_architecture_page_lists_the_layers_import_linter_enforces() -> None:
    contracts = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["importlinter"]["contracts"]
    (layers,) = [c["layers"] for c in contracts if c["type"] == "layers" and c["containers"] == ["rigidrel_app"]]
    page = (ROOT / "docs" / "architecture.md").read_text(encoding="utf-8")
    block = re.search(r"```\n((?:\s*\w+(?: \| \w+)*\n)+)\s*```", page)
    assert block, "docs/architecture.md has no code block of the layers"
    assert [line.strip() for line in block.group(1).splitlines()] == layers


#: Pages whose Python examples run in the fast lane; the notebook page's need a server or a kernel
#: (tests/test_notebook.py runs its first one).
EXAMPLE_PAGES = ("README.md", "docs/getting-started.md", "docs/core.md", "docs/causality.md", "docs/adding-a-scene.md")


def python_blocks(page: str) -> list[str]:
    return re.findall(r"```python\n(.*?)```", (ROOT / page).read_text(encoding="utf-8"), re.S)


@pytest.mark.parametrize("page", EXAMPLE_PAGES)
def test_the_python_examples_of_the_docs_run(page: str) -> None:
    """Every example that is a script (it starts with an import) runs as written; the others (a module's
    source, a fragment of one) at least compile. A scene an example registers is unregistered after it."""
    import rigidrel_core as rr

    blocks = python_blocks(page)
    assert blocks, f"{page} has no Python example"
    for k, block in enumerate(blocks):
        code = compile(block, f"{page} (example {k + 1})", "exec")
        if not block.startswith(("import ", "from ")) or "from . import" in block:
            continue
        before = set(rr.scene_descriptions())
        try:
            exec(code, {"__name__": f"docs_example_{k}"})
        finally:
            for kind in set(rr.scene_descriptions()) - before:
                rr.unregister_scene(kind)


def test_the_link_checker_finds_a_broken_link_and_a_missing_anchor(tmp_path: Path) -> None:
    (tmp_path / "a.html").write_text(
        '<h2 id="here">x</h2><a href="b.html#there">ok</a> <a href="#here">ok</a> <a href="https://example.org">out</a>'
        '<a href="b.html#nowhere">no anchor</a> <a href="c.html">no file</a> <img src="pic.png">'
        '<script src="https://cdn.example.org/x.js"></script>'
    )
    (tmp_path / "b.html").write_text('<p id="there">y</p>')
    problems = broken_links(tmp_path)
    assert len(problems) == 4, problems
    assert any("#nowhere" in p for p in problems) and any("c.html" in p for p in problems)
    assert any("pic.png" in p for p in problems) and any("network" in p for p in problems)


@pytest.mark.slow  # builds the whole site (mkdocs and mkdocstrings in a subprocess): about 10 s
def test_the_site_builds_strictly_and_every_internal_link_resolves(tmp_path: Path) -> None:
    site = tmp_path / "site"
    env = {**os.environ, "NO_MKDOCS_2_WARNING": "1"}
    command = [sys.executable, "-m", "mkdocs", "build", "--strict", "--config-file", str(ROOT / "mkdocs.yml")]
    build = subprocess.run(
        [*command, "--site-dir", str(site)],
        cwd=ROOT,
        env=env,
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert build.returncode == 0, f"mkdocs build --strict failed:\n{build.stdout}\n{build.stderr}"
    assert "WARNING" not in build.stderr, build.stderr
    pages = sorted(p.name for p in site.glob("*.html"))
    assert {"index.html", "api-core.html", "api-app.html", "changelog.html"} <= set(pages), pages
    problems = broken_links(site)
    assert not problems, "broken links in the built site:\n" + "\n".join(problems)
