"""Lorentz boosts along x (c = 1): the one-parameter group of rapidity shifts, and frames.

Convention: a frame moving with velocity ``beta`` along +x has coordinates

.. math::
    t' = \\gamma (t - \\beta x), \\qquad x' = \\gamma (x - \\beta t),

with the same origin as the lab. In rapidity ``psi = atanh(beta)``:
``t' = t cosh(psi) - x sinh(psi)``, ``x' = x cosh(psi) - t sinh(psi)``; boosting into the
frame subtracts ``psi`` from every rapidity, and boosts compose by adding rapidities.
Events are arrays whose last axis is ``(t, x)``.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from ._exact import REST, ExactVelocity
from ._validate import check_velocity

FloatArray = npt.NDArray[np.float64]


@dataclass(frozen=True)
class Boost:
    """A batch of boosts into frames of rapidity ``rapidity`` (``events_frame = boost @ events_lab``)."""

    rapidity: FloatArray
    """Frame rapidities ``psi``. Shape ``(*,)``."""

    @classmethod
    def identity(cls, batch_shape: tuple[int, ...] = ()) -> Boost:
        return cls(np.zeros(batch_shape))

    @classmethod
    def from_rapidity(cls, rapidity: npt.ArrayLike) -> Boost:
        return cls(np.asarray(rapidity, dtype=np.float64))

    @classmethod
    def from_velocity(cls, velocity: npt.ArrayLike) -> Boost:
        """``psi = atanh(beta)``; |beta| < 1."""
        beta = np.asarray(velocity, dtype=np.float64)
        return cls(np.arctanh(beta))

    def as_velocity(self) -> FloatArray:
        return np.tanh(self.rapidity)

    def as_lorentz_factor(self) -> FloatArray:
        return np.cosh(self.rapidity)

    def inverse(self) -> Boost:
        return Boost(-self.rapidity)

    def apply(self, events: npt.ArrayLike) -> FloatArray:
        """Boost events of shape ``(*, 2)`` = ``(t, x)``; batch axes broadcast."""
        e = np.asarray(events, dtype=np.float64)
        ch = np.cosh(self.rapidity)[..., None]
        sh = np.sinh(self.rapidity)[..., None]
        t = e[..., 0:1]
        x = e[..., 1:2]
        return np.concatenate([t * ch - x * sh, x * ch - t * sh], axis=-1)

    def __matmul__(self, other: Boost) -> Boost:
        """Composition: boosting by ``other`` and then by ``self`` adds rapidities."""
        return Boost(self.rapidity + other.rapidity)


@dataclass(frozen=True)
class Frame:
    """An inertial frame, given by its velocity relative to the lab (c = 1).

    The velocity is kept to double-double precision (:class:`ExactVelocity`), so a
    preset such as "rod 2 after" is the rod's rest frame to ~32 digits, not to the
    nearest float64.
    """

    velocity: ExactVelocity
    name: str = "custom"

    @classmethod
    def lab(cls) -> Frame:
        return cls(REST, "lab")

    @classmethod
    def from_velocity(cls, beta: float, name: str = "custom") -> Frame:
        """Frame moving with velocity ``beta`` along +x; ``beta`` in (-1, 1)."""
        return cls(ExactVelocity.from_float(check_velocity("frame_velocity", beta)), name)

    @property
    def beta(self) -> float:
        """The frame's velocity rounded to float64, ``|beta| < 1`` (see :attr:`ExactVelocity.value`)."""
        return self.velocity.value

    @property
    def rapidity(self) -> float:
        return self.velocity.rapidity()

    @property
    def lorentz_factor(self) -> float:
        return self.velocity.lorentz_factor()

    def sinh_rapidity(self) -> float:
        """``gamma beta``."""
        return self.velocity.proper_velocity()

    def cosh_rapidity_minus_one(self) -> float:
        """``gamma - 1 = (gamma beta)^2 / (gamma + 1)``, accurate for small ``beta``."""
        u = self.velocity.proper_velocity()
        return u * u / (math.sqrt(1.0 + u * u) + 1.0)

    def as_boost(self) -> Boost:
        return Boost(np.asarray(self.rapidity))

    def key(self) -> tuple[float, float]:
        return (self.velocity.hi, self.velocity.lo)


FrameLike = float | Frame


def as_frame(frame_velocity: FrameLike) -> Frame:
    """Accept a float velocity (validated) or a :class:`Frame`."""
    if isinstance(frame_velocity, Frame):
        return frame_velocity
    if type(frame_velocity) is float:
        return _frame_of_float(frame_velocity)
    return Frame.from_velocity(frame_velocity)


@functools.lru_cache(maxsize=256)
def _frame_of_float(beta: float) -> Frame:
    return Frame.from_velocity(beta)
