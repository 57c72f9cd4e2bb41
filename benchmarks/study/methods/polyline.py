"""Method 4: spacetimelib (PyPI, a real peer) with polyline worldlines.

spacetimelib has no hyperbolas: a worldline is a polyline through vertices ``[t, x]``,
straight between them. Each accelerated piece of :mod:`benchmarks.study.paper` becomes ``N``
vertices at equally spaced lab times from its start to its stop event, on the printed
formula; before the first and after the last vertex the worldline continues with the
paper's velocities (``past_vel_s``, ``future_vel_s``). A kicked end is one vertex.
Then, with spacetimelib's own API: ``st.Worldline(vertices, ...)``, ``.boost([beta])``
(vertices by the boost matrix, end velocities by velocity addition) and ``.eval(t')`` per
frame time (a scalar call; x' is the event's second component).

A chord of a hyperbola stays a chord under a boost, so the error is the chord's sagitta,
``~ (Delta t)^2 / (8 rho)``: it falls as ``N^-2``.
"""

from __future__ import annotations

import numpy as np
import spacetimelib as st

from ..paper import PaperEnd, paper_ends
from ..scenes import BenchScene
from . import FloatArray


def worldline(end: PaperEnd, n_vertices: int) -> st.Worldline:
    """The end's lab worldline as a spacetimelib polyline (``N`` vertices on the accelerated piece)."""
    if end.form == "kick":
        vertices = np.array([[end.t_start, end.x_start]])
    else:
        t = np.linspace(end.t_start, end.t_stop, n_vertices)
        vertices = np.stack([t, end.accelerated_x(t)], axis=-1)
    return st.Worldline(vertices, past_vel_s=[end.v_before], future_vel_s=[end.v_after])


def positions(scene: BenchScene, frame_velocity: float, t: FloatArray, n_vertices: int) -> FloatArray:
    """Both ends of each rod at frame times ``t``, by ``Worldline.boost`` and ``Worldline.eval``."""
    times = t.tolist()
    out = []
    for rod in paper_ends(scene):
        ends = []
        for end in rod:
            boosted = worldline(end, n_vertices).boost([frame_velocity])
            ends.append([float(np.asarray(boosted.eval(s))[1]) for s in times])
        out.append(ends)
    return np.array(out)
