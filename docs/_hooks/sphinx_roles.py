"""Griffe extension: the code's reStructuredText docstrings read as Markdown in the API reference.

The docstrings write cross-references as Sphinx roles (``:func:`~rigidrel_core.build_scene```),
display formulas as ``.. math::`` blocks and literal blocks after ``::``. mkdocstrings renders
Markdown, so each role becomes inline code of the name it shows (``~`` keeps the last part, as
Sphinx does; a leading ``.`` is dropped), a formula block becomes a fenced LaTeX block, and a
paragraph's closing ``::`` a single colon (the indented block after it is code in Markdown too).
"""

from __future__ import annotations

import re
import textwrap
from typing import Any

import griffe

ROLE = re.compile(r":(?:func|class|meth|mod|data|attr|exc|obj):`([^`]+)`")
MATH = re.compile(r"^([ \t]*)\.\. math::[ \t]*\n((?:\1[ \t]+\S.*\n?|[ \t]*\n)+)", re.M)


def _role(m: re.Match[str]) -> str:
    target = m.group(1).strip()
    if target.startswith("~"):
        target = target[1:].rsplit(".", 1)[-1]
    return f"`{target.lstrip('.')}`"


def _math(m: re.Match[str]) -> str:
    indent, body = m.group(1), textwrap.dedent(m.group(2)).strip("\n")
    fenced = "\n".join(f"{indent}{line}" if line else "" for line in ["```latex", *body.splitlines(), "```"])
    return fenced + "\n\n"


def markdown(text: str) -> str:
    """``text`` (a docstring) with its roles, formula blocks and ``::`` as Markdown."""
    text = MATH.sub(_math, text)
    text = ROLE.sub(_role, text)
    return re.sub(r"(\S)::[ \t]*$", r"\1:", text, flags=re.M)


class SphinxRoles(griffe.Extension):
    def on_instance(self, *, obj: griffe.Object, **kwargs: Any) -> None:
        if obj.docstring is not None:
            obj.docstring.value = markdown(obj.docstring.value)
