"""The paper's canonical cases (Franklin 2012): the parameter values of Figs. 1, 3 and 4, as printed.

One definition, in the registry's parameter names: the scenes' presets are these values, and
:mod:`rigidrel_core.examples` builds its named scenes from them. Lengths in units of the rest length
L0 = 1, masses in units of M1; c = 1.
"""

from __future__ import annotations

from collections.abc import Mapping
from types import MappingProxyType

#: The paper's final velocity in Figs. 1-4: V = 0.6, gamma = 1.25.
PAPER_V = 0.6

#: Fig. 1, solid curve: constant acceleration to V = 0.6 with a'_F = 1/(2 L0) (so a'_B = 1/L0).
FIG1_CONSTANT_ACCELERATION: Mapping[str, float | None] = MappingProxyType(
    {"v": PAPER_V, "length": 1.0, "a_front": 0.5, "mass": 1.0}
)
#: Fig. 3, case I: M2 = 2 M1, V1 = 0.6, V2 = 0, equal rest lengths, elastic.
FIG3_CASE_ONE: Mapping[str, float | None] = MappingProxyType(
    {"v1": PAPER_V, "v2": 0.0, "length1": 1.0, "length2": 1.0, "eps": 1.0, "mass1": 1.0, "mass2": 2.0}
)
#: Fig. 4, case II: M1 = 2 M2 (M2 = M1/2), V1 = 0.6, V2 = 0, equal rest lengths, elastic.
FIG4_CASE_TWO: Mapping[str, float | None] = MappingProxyType(
    {"v1": PAPER_V, "v2": 0.0, "length1": 1.0, "length2": 1.0, "eps": 1.0, "mass1": 1.0, "mass2": 0.5}
)
