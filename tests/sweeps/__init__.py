"""Full sweeps: the whole sets that the suite checks only a representative part of.

A test that sweeps a set (pages × screen sizes, random charts, command lines) takes its cases from
:func:`cases`: the representative ones (each kind, each extreme, each size at least once) in the
suite, all of them when ``RIGIDREL_FULL_SWEEP=1``. Each module here runs one such sweep, through
pytest and every lane (its docstring says what it sweeps)::

    python -m tests.sweeps.export_pages
    python -m tests.sweeps.placement_seeds
    python -m tests.sweeps.cli_subprocess

None of these modules is collected by pytest (their names do not start with ``test_``).
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from pathlib import Path
from typing import TypeVar

T = TypeVar("T")

ROOT = Path(__file__).resolve().parents[2]


def cases(representative: Sequence[T], full: Sequence[T]) -> list[T]:
    """``full`` when the full sweep is asked for (``RIGIDREL_FULL_SWEEP=1``), else ``representative``
    (which must be a part of ``full``)."""
    missing = [c for c in representative if c not in full]
    assert not missing, f"representative cases outside the full sweep: {missing}"
    return list(full if os.environ.get("RIGIDREL_FULL_SWEEP") == "1" else representative)


def run(*tests: str) -> int:
    """Run ``tests`` (pytest node ids, from the repository's root) over their full sweep, in every lane."""
    import pytest

    os.environ["RIGIDREL_FULL_SWEEP"] = "1"
    os.chdir(ROOT)
    return int(pytest.main(["-q", "-m", "", "-p", "no:cacheprovider", *tests]))
