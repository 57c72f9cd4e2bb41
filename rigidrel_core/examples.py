"""Canonical named cases from Franklin (2012), reused by the tests, the app's presets and the figures.

Lengths in units of the rest length L0 = 1; c = 1.
"""

from __future__ import annotations

from ._scene import Scene
from .scenes.acceleration import constant_acceleration
from .scenes.collision import rod_collision
from .scenes.impulse import impulsive_start

#: The paper's final velocity in Figs. 1-4: V = 0.6, gamma = 1.25.
PAPER_V = 0.6


def fig1_constant_acceleration() -> Scene:
    """Fig. 1, solid curve: V = 0.6, a'_F = 1/(2 L0), a'_B = 1/L0."""
    return constant_acceleration(v=PAPER_V, length=1.0, a_front=0.5)


def fig1_impulsive_start() -> Scene:
    """Fig. 1, dashed curve: the back end jumps to V = 0.6; a'_F = 1/L0."""
    return impulsive_start(v=PAPER_V, length=1.0)


def fig3_case_one() -> Scene:
    """Fig. 3, case I: M2 = 2 M1, V1 = 0.6, V2 = 0, equal rest lengths, elastic."""
    return rod_collision(v1=PAPER_V, v2=0.0, mass1=1.0, mass2=2.0, length1=1.0, length2=1.0, eps=1.0)


def fig4_case_two() -> Scene:
    """Fig. 4, case II: M1 = 2 M2, V1 = 0.6, V2 = 0, equal rest lengths, elastic."""
    return rod_collision(v1=PAPER_V, v2=0.0, mass1=2.0, mass2=1.0, length1=1.0, length2=1.0, eps=1.0)
