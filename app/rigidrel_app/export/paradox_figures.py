"""Figures of the two paradoxes in the paper's print style, with captions that state the verdicts.

Bell's spaceships (V = 0.6, s = 1, a = 0.5, breaking strain 0.25) and the pole in the barn
(V = 0.8, L0 = 1, D = 0.6), each a lab Minkowski diagram sampled exactly from the core; every
number in a caption is the core's.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

import rigidrel_core as rr

from ..view.sampling import sample_worldlines
from ..view.vocabulary import Area, Chart, Dash, Item, Label, Points, Polyline, Style, event_label
from .figures import _PLOT_AREA, _PNG_SCALE, FIGURE_TOLERANCE_PX, PaperFigure, _ranges, write_figures

_BLACK = "#000000"
_GREY = "#555555"


def _rod(
    scene: rr.Scene,
    rod: int,
    t_range: tuple[float, float],
    x_range: tuple[float, float],
    color: str,
    dash: Dash = "solid",
    shade: bool = True,
) -> list[Item]:
    px_per_x = _PNG_SCALE * _PLOT_AREA[0] / (x_range[1] - x_range[0])
    left, right = sample_worldlines(scene, rr.LAB, np.array([0.0, 1.0]), t_range, px_per_x, FIGURE_TOLERANCE_PX)[rod]
    items: list[Item] = []
    if shade:
        items.append(
            Area(
                np.concatenate([left.x, right.x[::-1]]),
                np.concatenate([left.t, right.t[::-1]]),
                Style("rgba(0,0,0,0.07)", 0.0),
            )
        )
    items += [Polyline(w.x, w.t, Style(color, 2.0, dash)) for w in (left, right)]
    return items


def _event(t: float, x: float, name: str, anchor: str = "left") -> list[Item]:
    return [
        Points(np.array([x]), np.array([t]), Style(_BLACK), size=7),
        Label(x, t, name, Style(_BLACK), anchor="right" if anchor == "right" else "left", size=15),
    ]


def bell_figure() -> PaperFigure:
    scene = rr.bell_spaceships(0.6, 1.0, 0.5, breaking_strain=0.25)
    t_range = (-0.3, 2.6)
    x_range, t_range = _ranges(scene, t_range)
    items: list[Item] = [
        *_rod(scene, 0, t_range, x_range, _BLACK),
        *_rod(scene, 1, t_range, x_range, _BLACK),
        *_rod(scene, 2, t_range, x_range, _GREY, "dash", shade=False),
    ]
    for n, side in (("T_B1", "right"), ("T_B2", "left"), ("T_Frod", "left")):
        t, x = scene.events[n]
        items += _event(t, x, event_label(n), side)
    broken = scene.string_break
    assert broken is not None
    items += _event(broken[0], broken[1], "break", "right")
    g = scene.rods[0].motion.velocity_final.lorentz_factor()
    caption = (
        "Bell's spaceships: two ships (solid) whose rear ends have the same proper acceleration a = 0.5 start "
        "1 apart and reach V = 0.6 at the same lab time, T_B1 and T_B2 (t = γV/a = 1.5): their rear ends stay "
        f"1 apart in the lab and end γs = {g:.4g} apart in the ships' frame. The string from the rear ship's "
        f"front to the front ship's rear stretches from rest length {scene.string_unstretched:.4g} to "
        f"{scene.string_final:.4g} (strain {scene.final_strain:.3g}): at breaking strain 0.25 it breaks at "
        f"(t, x) = ({broken[0]:.4g}, {broken[1]:.4g}). The Born-rigid rod on the same rear ends (dashed) keeps its "
        "rest length 1: its front accelerates less, a/(1 + a s) (Eq. (15)), and reaches V only at T_Frod."
    )
    return PaperFigure("bell-spaceships", caption, Chart(tuple(items), "x", "t", x_range, t_range, equal_aspect=True))


def pole_barn_figure() -> PaperFigure:
    scene = rr.pole_barn(0.8, 1.0, 0.6, model="both")
    t_range = (-1.8, 1.2)
    x_range, t_range = _ranges(scene, t_range)
    tt = np.array(t_range)
    items: list[Item] = [
        Polyline(np.zeros(2), tt, Style(_GREY, 5.0)),
        Polyline(np.full(2, scene.barn_length), tt, Style(_GREY, 2.0, "dash")),
        *_rod(scene, 0, t_range, x_range, _BLACK),
        *_rod(scene, 1, t_range, x_range, _GREY, "dash", shade=False),
    ]
    for n, side in (("T_1", "left"), ("T_1'", "left"), ("T_s", "left")):
        t, x = scene.events[n]
        items += _event(t, x, event_label(n), side)
    t_d, x_d = scene.door_closing
    items += _event(t_d, x_d, "door closes", "right")
    born, signal = scene.verdicts()
    caption = (
        "The pole in the barn, V = 0.8, L0 = 1, barn D = L0/γ = 0.6 (back wall at x = 0, door dashed at x = 0.6, "
        f"closing at t = {t_d:g}). Solid: the Born-rigid stop (Sec. 5, ε = 0): its rear end starts braking at T_1, "
        f"before the contact, and comes to rest at x = {born.rear_rest_x:.4g}; it "
        f"{'is' if born.inside_barn_frame else 'is never'} entirely inside the barn, in the barn's frame and in the "
        f"pole's, and the door closes {born.door_barn_frame.value}. Dashed: the signal-limited stop (c_s = 1): "
        f"every point moves on until the stop front from the contact reaches it; the rear end stops at T_s, "
        f"x = {signal.rear_rest_x:.4g}; it {'is' if signal.inside_barn_frame else 'is never'} entirely inside, in "
        f"both frames, and the door closes {signal.door_barn_frame.value}."
    )
    return PaperFigure("pole-barn", caption, Chart(tuple(items), "x", "t", x_range, t_range, equal_aspect=True))


def paradox_figures() -> list[PaperFigure]:
    return [bell_figure(), pole_barn_figure()]


def write_paradox_figures(out: Path) -> list[Path]:
    """Both figures as SVG and PNG in ``out``, and their captions as ``<name>.txt``."""
    return write_figures(out, paradox_figures(), captions=True)
