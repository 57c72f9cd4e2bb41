"""Canonical named cases from Franklin (2012), reused by the tests, the app's presets and the figures.

The values are :mod:`rigidrel_core._paper`'s, which the scenes' presets are too (Figs. 1, 3 and 4).
Lengths in units of the rest length L0 = 1; c = 1.
"""

from __future__ import annotations

from ._paper import FIG1_CONSTANT_ACCELERATION as FIG1_CONSTANT_ACCELERATION
from ._paper import FIG3_CASE_ONE as FIG3_CASE_ONE
from ._paper import FIG4_CASE_TWO as FIG4_CASE_TWO
from ._paper import PAPER_V as PAPER_V
from ._scene import Scene
from .scenes.acceleration import CONSTANT_ACCELERATION
from .scenes.collision import ROD_COLLISION


def fig1_constant_acceleration() -> Scene:
    """Fig. 1, solid curve: V = 0.6, a'_F = 1/(2 L0), a'_B = 1/L0."""
    return CONSTANT_ACCELERATION.build(**FIG1_CONSTANT_ACCELERATION)


def fig1_impulsive_start() -> Scene:
    """Fig. 1, dashed curve: the back end jumps to V = 0.6; a'_F = 1/L0 (the preset's overlay)."""
    overlay = CONSTANT_ACCELERATION.overlay
    assert overlay is not None
    return overlay.build(FIG1_CONSTANT_ACCELERATION)


def fig3_case_one() -> Scene:
    """Fig. 3, case I: M2 = 2 M1, V1 = 0.6, V2 = 0, equal rest lengths, elastic."""
    return ROD_COLLISION.build(**FIG3_CASE_ONE)


def fig4_case_two() -> Scene:
    """Fig. 4, case II: M1 = 2 M2, V1 = 0.6, V2 = 0, equal rest lengths, elastic."""
    return ROD_COLLISION.build(**FIG4_CASE_TWO)
