"""Entry point of ``rigidrel bench`` (being written)."""

from __future__ import annotations


def run_bench(quick: bool, out: str) -> int:
    raise NotImplementedError("rigidrel bench is being written")
