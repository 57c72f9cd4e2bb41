r"""Inertial frames along x (c = 1): the one-parameter group of Lorentz boosts.

Convention: a frame moving with velocity ``beta`` along +x has coordinates

.. math::
    t' = \gamma (t - \beta x), \qquad x' = \gamma (x - \beta t),

with the same origin as the lab. In rapidity ``psi = atanh(beta)`` boosting into the
frame subtracts ``psi`` from every rapidity, and boosts compose by adding rapidities.

A :class:`Frame` is both the frame and the boost into it: ``frame @ events_lab`` maps lab
events (arrays whose last axis is ``(t, x)``) into the frame, and ``frame_b @ frame_a`` is
the frame moving with velocity ``beta_b`` relative to frame ``a`` (``(frame_b @ frame_a) @ e
== frame_b @ (frame_a @ e)``).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import overload

import numpy as np
import numpy.typing as npt

from ._exact import REST, ExactVelocity, compose_velocities, relative_rapidity, velocity_from_rapidity
from ._validate import ParameterError, as_real, check_velocity

FloatArray = npt.NDArray[np.float64]


@dataclass(frozen=True, init=False)
class Frame:
    """An inertial frame: its velocity relative to the lab (c = 1) and an optional name.

    The velocity is kept to double-double precision (:class:`ExactVelocity`), so a preset
    such as "rod 2 after" is the rod's rest frame to ~32 digits, not to the nearest float64.
    Frames of one velocity and different names are different values; :meth:`same_velocity`
    compares velocities alone.
    """

    velocity: ExactVelocity
    name: str | None = None

    def __init__(self, velocity: ExactVelocity, name: str | None = None) -> None:
        # into the instance's dict, not through one object.__setattr__ call each (the generated
        # __init__): a scene makes its frame presets on every slider change
        fields = self.__dict__
        fields["velocity"] = velocity
        fields["name"] = name

    # ------------------------------------------------------------------ constructors
    @classmethod
    def lab(cls) -> Frame:
        """The lab frame S (velocity 0)."""
        return LAB

    @classmethod
    def from_velocity(cls, beta: float, name: str | None = None) -> Frame:
        """The frame moving with velocity ``beta`` along +x; ``ValueError`` unless ``|beta| < 1``."""
        return cls(ExactVelocity.from_float(check_velocity("beta", beta)), name)

    @classmethod
    def from_rapidity(cls, rapidity: float, name: str | None = None) -> Frame:
        """The frame of rapidity ``psi`` (``beta = tanh psi``), ``|psi| <= 700``, the float ``psi``
        taken as exact: ``tanh psi = expm1(2 psi)/(expm1(2 psi) + 2)`` and ``1 - |tanh psi| =
        2/(exp(2|psi|) + 1)`` to double-double, so that the velocity and its gap to light speed agree
        and rapidities of frames add exactly under ``@``."""
        allowed = "a finite number with |rapidity| <= 700"
        psi = as_real("rapidity", rapidity, allowed)  # also refuses what is not a number at run time
        if not abs(psi) <= 700.0:
            raise ParameterError("rapidity", allowed, rapidity)
        return cls(velocity_from_rapidity(psi), name)

    # ------------------------------------------------------------------ views
    @property
    def beta(self) -> float:
        """The frame's velocity rounded to float64, ``|beta| < 1`` (see :attr:`ExactVelocity.value`)."""
        return self.velocity.value

    @property
    def rapidity(self) -> float:
        """``psi = atanh(beta)``."""
        return self.velocity.rapidity()

    @property
    def lorentz_factor(self) -> float:
        """``gamma = cosh(psi)``."""
        return self.velocity.lorentz_factor()

    @property
    def proper_velocity(self) -> float:
        """``gamma beta = sinh(psi)``."""
        return self.velocity.proper_velocity()

    def lorentz_factor_minus_one(self) -> float:
        """``gamma - 1 = (gamma beta)^2 / (gamma + 1)``, accurate for small ``beta``
        (:meth:`ExactVelocity.lorentz_factor_minus_one`)."""
        return self.velocity.lorentz_factor_minus_one()

    def doppler_factors(self) -> tuple[float, float]:
        """``(exp(psi), exp(-psi)) = (gamma (1 + beta), gamma (1 - beta))``, each to a few ulp."""
        g = self.velocity.lorentz_factor()
        return g * self.velocity.one_plus(), g * self.velocity.one_minus()

    def same_velocity(self, other: Frame) -> bool:
        """Whether the two frames move with exactly the same velocity (names aside)."""
        return self.key() == other.key()

    def key(self) -> tuple[float, float]:
        """The exact velocity as a hashable pair (names aside)."""
        return (self.velocity.hi, self.velocity.lo)

    def label(self) -> str:
        """The name, or ``"β = 0.5"`` for an unnamed frame."""
        return self.name if self.name is not None else f"β = {self.beta:.4g}"

    # ------------------------------------------------------------------ the group
    def inverse(self) -> Frame:
        """The boost back: the lab seen from this frame moves with ``-beta``."""
        return Frame(self.velocity.negated(), None)

    def rapidity_relative_to(self, other: Frame) -> float:
        """The rapidity of this frame seen from ``other``, ``psi - psi_other`` (a number, not a frame;
        the frame itself is ``self @ other.inverse()``), to a few ulp of itself."""
        return relative_rapidity(self.velocity, other.velocity)

    @overload
    def __matmul__(self, other: Frame) -> Frame: ...

    @overload
    def __matmul__(self, other: npt.ArrayLike) -> FloatArray: ...

    def __matmul__(self, other: Frame | npt.ArrayLike) -> Frame | FloatArray:
        """``frame_b @ frame_a``: composition (rapidities add); ``frame @ events``: lab events into the frame.

        Events are arrays of shape ``(..., 2)`` holding ``(t, x)``. The map is applied in
        light-cone coordinates, ``t - x -> exp(psi) (t - x)`` and ``t + x -> exp(-psi) (t + x)``,
        so an event on the light cone stays exactly on it and nothing is cancelled.
        """
        if isinstance(other, Frame):
            if other.key() == (0.0, 0.0):
                return Frame(self.velocity, None)
            if self.key() == (0.0, 0.0):
                return Frame(other.velocity, None)
            try:
                return Frame(compose_velocities(self.velocity, other.velocity), None)
            except ValueError:
                raise ParameterError("frame", "frames whose composed speed is below light speed", other) from None
        return self.apply(other)

    def apply(self, events_lab: npt.ArrayLike) -> FloatArray:
        """``self @ events_lab`` (see :meth:`__matmul__`)."""
        e = _events("events", events_lab)
        if self.key() == (0.0, 0.0):  # the lab's own coordinates: the identity, exactly
            return e.copy()
        up, down = self.doppler_factors()
        t, x = e[..., 0], e[..., 1]
        u = (t - x) * up  # t' - x'
        w = (t + x) * down  # t' + x'
        return np.stack([0.5 * (u + w), 0.5 * (w - u)], axis=-1)


def _events(name: str, events: npt.ArrayLike) -> FloatArray:
    allowed = "a real array of shape (..., 2) holding (t, x)"
    try:
        arr = np.asarray(events)
    except (TypeError, ValueError):
        raise ParameterError(name, allowed, events) from None
    if arr.dtype.kind not in "biuf" or arr.ndim == 0 or arr.shape[-1] != 2:
        raise ParameterError(name, allowed, events)
    return arr.astype(np.float64, copy=False)


#: The lab frame S.
LAB = Frame(REST, "lab")


def check_frame(frame: object) -> Frame:
    """The argument of every sampler: a :class:`Frame` (one frame type everywhere)."""
    if not isinstance(frame, Frame):
        raise ParameterError(
            "frame",
            "a rigidrel_core.Frame, e.g. Frame.from_velocity(0.5) or scene.frame('rod after')",
            frame,
        )
    return frame
