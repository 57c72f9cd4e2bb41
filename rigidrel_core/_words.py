"""Events and frames in words, each coordinate pair labelled with the frame it belongs to.

Every sentence the core writes beside numbers (a paradox's notes, the causal verdicts) gives its
events through :func:`event_in_words`: ``"(lab t, x) = (1.26, 0.449)"`` in the lab,
``"(t, x) = (0.6, 1) in the frame 'pole before' (β = -0.6)"`` in any other frame, so that no
coordinate pair reads as an invariant and none is given under another frame's tables (c = 1).
"""

from __future__ import annotations

from ._frame import LAB, Frame

#: A value at most this fraction of the size of the terms it was formed from is rounding noise at
#: every precision a text shows (at most 10 significant digits): it is shown as 0.
NOISE = 1e-12


def shown(value: float, scale: float) -> float:
    """``value`` as a text shows it: ``0.0`` if it is at most :data:`NOISE` of ``scale``, the size of
    the terms it was formed from (a total of opposite momenta, a boost of an event), else itself."""
    return 0.0 if abs(value) <= NOISE * scale else value + 0.0


def event_shown(event: tuple[float, float], frame: Frame) -> tuple[float, float]:
    """An event ``(t', x')`` of ``frame`` as a text shows it: each coordinate that is rounding noise of
    the boost that formed it, at most :data:`NOISE` of ``gamma (|t| + |beta x|)`` (of ``gamma (|x| +
    |beta t|)``) of the lab event's terms, as 0. In the lab no coordinate changes but ``-0``."""
    t, x = event
    g, b = frame.lorentz_factor, frame.beta
    t_lab, x_lab = g * (t + b * x), g * (x + b * t)
    return (shown(t, g * (abs(t_lab) + abs(b * x_lab))), shown(x, g * (abs(x_lab) + abs(b * t_lab))))


def is_lab(frame: Frame) -> bool:
    """Whether ``frame`` moves with the lab (whatever its name)."""
    return frame.same_velocity(LAB)


def frame_in_words(frame: Frame) -> str:
    """``"the lab"``, ``"the frame 'pole before' (β = -0.6)"`` or ``"the frame β = 0.3"``."""
    if is_lab(frame):
        return "the lab"
    if frame.name is None:
        return f"the frame β = {frame.beta:.4g}"
    return f"the frame '{frame.name}' (β = {frame.beta:.4g})"


def event_in_words(event: tuple[float, float], frame: Frame, digits: int = 4) -> str:
    """An event ``(t', x')`` of ``frame`` in words, its frame named: ``"(lab t, x) = (1, 1)"`` in the
    lab, ``"(t, x) = (0.7338, 0.7338) in the frame 'custom' (β = 0.3)"`` elsewhere (``digits``
    significant digits, and no ``-0``)."""
    t, x = (f"{v:.{digits}g}" for v in event_shown(event, frame))
    if is_lab(frame):
        return f"(lab t, x) = ({t}, {x})"
    return f"(t, x) = ({t}, {x}) in {frame_in_words(frame)}"
