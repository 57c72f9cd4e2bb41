"""The 50-digit reference: the paper's lab formulas in mpmath, sliced at frame times by root finding.

Independent of :mod:`rigidrel_core` by construction (it never imports it; units c = 1):

* scene solutions follow the paper's own route at 50 digits: rapidities via ``atanh``,
  the barycentric velocity ``u = (m1 g1 V1 + m2 g2 V2)/(m1 g1 + m2 g2)`` (Sec. 6, Eq. (26)),
  velocity addition ``(V - u)/(1 - u V)`` into and out of the barycentric frame, Eq. (29)
  for the restitution (the core uses proper-velocity algebra in double-double);
* worldlines are the paper's lab formulas, point by point: Eq. (4)
  ``x = xi + (sqrt(1 + a'^2 t^2) - 1)/a'`` for constant acceleration with each point's own
  ``a' = 1/(xi + 1/a'_B)`` (Eq. (15)), Eq. (20) ``x = sqrt(L0^2 + t^2)`` for impulses,
  ``t -> -t`` for deceleration, Eqs. (22)-(23) for collisions;
* each worldline carries its clock: the proper time ``tau(t)`` at lab time ``t``, integrated
  piece by piece in the lab (``d tau = sqrt(1 - v^2) dt``; on a hyperbola of rest-distance
  ``rho`` from its centre ``tau = rho asinh(t/rho)`` + const), reading 0 at the lab time
  where the point starts changing velocity (the core's convention);
  :func:`proper_time_by_quadrature` integrates ``sqrt(1 - (dx/dt)^2)`` from ``x(t)`` alone
  as a cross-check of those closed forms;
* a slice at frame time ``t'`` solves ``gamma (t - beta x(t)) = t'`` for the lab time ``t``
  (strictly increasing in ``t``) by bracketing root finding, then boosts:
  ``x' = gamma (x(t) - beta t)``, and reads the clock there: ``tau(t)`` (an invariant). The
  core never inverts anything: it evaluates closed forms in the frame.

One module per scene family holds that family's builders and the cases of the committed
table (:class:`SceneReference` s in a module-level ``SCENES`` tuple); :func:`discover` finds
them, so adding a scene to the reference is one new module here. This package holds what
they share: numbers (:func:`F`, :func:`gamma_of`), worldlines, frame slices and boosts.

Precision: every function here computes at :data:`REFERENCE_DIGITS` decimal digits in a
local context (``mp.workdps``); importing or using the package leaves mpmath's global
precision alone. The worldlines a builder returns compute at their caller's precision:
:func:`frame_slice` evaluates them at :data:`REFERENCE_DIGITS`, and arithmetic on the
returned numbers belongs inside :func:`reference_precision`.

Used at run time by ``rigidrel bench`` (the mpmath method and the reference for every
other method) and by ``tests/reference/make_reference.py`` (the committed table of the
accuracy tests). mpmath ships without precise type hints: its numbers are typed ``Any``.
"""

from __future__ import annotations

import functools
import importlib
import itertools
import pkgutil
import random
from collections.abc import Callable, Mapping
from contextlib import AbstractContextManager
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any, Literal, ParamSpec, TypeVar

import mpmath as mp

#: Working precision of the reference (decimal digits).
REFERENCE_DIGITS = 50

#: An mpmath number (mpmath ships no precise type hints).
Mp = Any
#: A function of lab time (a position or a clock reading).
OfTime = Callable[[Mp], Mp]
#: How a frame slice finds its lab time: plain bisection (the committed table), or the
#: Anderson-Bjorck bracketing secant (same bracket and tolerance, about 10x fewer steps).
SliceSolver = Literal["bisection", "anderson-bjorck"]
#: A scene's parameters as its constructor takes them (``None``: an optional one left out).
Parameters = Mapping[str, float | None]

_P = ParamSpec("_P")
_R = TypeVar("_R")


# ------------------------------------------------------------------ precision
def reference_precision() -> AbstractContextManager[Any]:
    """A ``with`` block computing at :data:`REFERENCE_DIGITS` digits (mpmath's global precision is restored)."""
    return mp.workdps(REFERENCE_DIGITS)


def at_reference_precision(fn: Callable[_P, _R]) -> Callable[_P, _R]:
    """``fn`` computing at :data:`REFERENCE_DIGITS` digits, whatever the caller's precision."""

    @functools.wraps(fn)
    def at_digits(*args: _P.args, **kwargs: _P.kwargs) -> _R:
        if mp.mp.dps == REFERENCE_DIGITS:
            return fn(*args, **kwargs)
        with mp.workdps(REFERENCE_DIGITS):
            return fn(*args, **kwargs)

    return at_digits


# ------------------------------------------------------------------ numbers
def F(x: float) -> Mp:
    """A float taken as exact."""
    return mp.mpf(float(x))


@at_reference_precision
def gamma_of(v: Mp) -> Mp:
    """``gamma = 1/sqrt(1 - v^2)`` (harmless at 50 digits)."""
    return 1 / mp.sqrt(1 - v * v)


@dataclass(frozen=True)
class Worldline:
    """One material point in the lab: its position ``x(t)`` and its clock ``tau(t)`` at lab time ``t``.

    The point is inertial before lab time ``start`` and after ``stop`` and changes velocity in
    between (``start == stop``: a kink, an impulse). Its clock reads ``tau(start) = 0`` and
    grows by ``d tau = sqrt(1 - (dx/dt)^2) dt``: negative before the change, whatever frame
    it is read from.
    """

    x: OfTime
    tau: OfTime
    start: Mp
    stop: Mp


@dataclass(frozen=True)
class RefScene:
    """Reference description: per rod, a lab worldline for each material fraction."""

    worldlines: list[list[Worldline]]
    """``[rod][fraction]``: position and clock of that material point."""
    events: dict[str, tuple[Mp, Mp]]
    """Named events as lab ``(t, x)``, in the paper's notation (the core's names)."""
    initial_velocities: list[Mp]
    final_velocities: list[Mp]
    lengths_rest: list[Mp]
    extra: dict[str, Mp]
    """Derived numbers worth tabulating (``"u"``: the barycentric velocity, ``"heat"``, ...)."""


# ------------------------------------------------------------------ worldlines
@at_reference_precision
def accelerating_point(xi: Mp, alpha: Mp, V: Mp) -> Worldline:
    """Sec. 3, Eq. (4): a point at rest at xi for t <= 0, proper acceleration alpha until speed V,
    reached at ``T = gamma V / alpha`` and ``X = xi + (gamma - 1)/alpha`` (Eqs. (9), (8)).

    Its clock: ``d tau = dt / gamma`` with ``gamma = sqrt(1 + alpha^2 t^2)`` (Eq. (7)), so
    ``tau = asinh(alpha t)/alpha`` while it accelerates, ``tau = t`` at rest before and
    ``tau = asinh(alpha T)/alpha + (t - T) sqrt(1 - V^2)`` after.
    """
    T = gamma_of(V) * V / alpha
    X = xi + (gamma_of(V) - 1) / alpha
    tau_T = mp.asinh(alpha * T) / alpha
    slow = mp.sqrt(1 - V * V)

    def x(t: Mp) -> Mp:
        if t <= 0:
            return xi
        if t <= T:
            return xi + (mp.sqrt(1 + alpha * alpha * t * t) - 1) / alpha
        return X + V * (t - T)

    def tau(t: Mp) -> Mp:
        if t <= 0:
            return t
        if t <= T:
            return mp.asinh(alpha * t) / alpha
        return tau_T + (t - T) * slow

    return Worldline(x, tau, mp.mpf(0), T)


@at_reference_precision
def hyperbola_point(centre: Mp, d: Mp, side: int, v_before: Mp, v_after: Mp) -> Worldline:
    """A point at rest-distance d from a centre event (0, centre) on side +1/-1.

    Sec. 5, Eq. (23): x = centre + side sqrt(d^2 + t^2) between the times where its velocity
    is v_before and v_after, ``t_0 = side d gamma_0 v_before`` and ``t_1 = side d gamma_1 v_after``;
    the tangent lines outside. Its clock: ``d tau = sqrt(1 - (dx/dt)^2) dt = d dt/sqrt(d^2 + t^2)``
    on the hyperbola, so ``tau = d (asinh(t/d) - asinh(t_0/d))`` there (0 for ``d = 0``: a
    kink), ``(t - t_0) sqrt(1 - v_before^2)`` before and ``tau(t_1) + (t - t_1) sqrt(1 - v_after^2)``
    after.
    """

    def t_at(v: Mp) -> Mp:  # dx/dt = side t / sqrt(d^2 + t^2) = v
        return side * d * gamma_of(v) * v

    t0, t1 = t_at(v_before), t_at(v_after)
    x0 = centre + side * d * gamma_of(v_before)
    x1 = centre + side * d * gamma_of(v_after)
    slow0, slow1 = mp.sqrt(1 - v_before * v_before), mp.sqrt(1 - v_after * v_after)

    def x(t: Mp) -> Mp:
        if t < t0:
            return x0 + v_before * (t - t0)
        if t > t1:
            return x1 + v_after * (t - t1)
        return centre + side * mp.sqrt(d * d + t * t)

    def on_hyperbola(t: Mp) -> Mp:
        return d * (mp.asinh(t / d) - mp.asinh(t0 / d)) if d != 0 else mp.mpf(0)

    tau1 = on_hyperbola(t1)

    def tau(t: Mp) -> Mp:
        if t < t0:
            return (t - t0) * slow0
        if t > t1:
            return tau1 + (t - t1) * slow1
        return on_hyperbola(t)

    return Worldline(x, tau, t0, t1)


@at_reference_precision
def time_reversed(w: Worldline) -> Worldline:
    """``w`` run backwards in lab time (deceleration is acceleration with ``t -> -t``):
    ``x_r(t) = x(-t)``; its change starts at ``-stop``, where its clock reads 0:
    ``tau_r(t) = tau(stop) - tau(-t)``."""
    tau_stop = w.tau(w.stop)
    return Worldline(lambda t: w.x(-t), lambda t: tau_stop - w.tau(-t), -w.stop, -w.start)


@at_reference_precision
def proper_time_by_quadrature(w: Worldline, t: Mp) -> Mp:
    """The clock at lab time ``t`` from the position alone: ``int_start^t sqrt(1 - (dx/dt)^2) dt``
    (negative before ``start``), ``dx/dt`` by mpmath's numerical differentiation of ``w.x`` and
    the integral by ``mp.quad`` split at ``start`` and ``stop`` (where ``dx/dt`` jumps or bends).
    An independent check of the closed forms in ``w.tau``; slow (seconds a reading)."""

    def rate(s: Mp) -> Mp:
        v = mp.diff(w.x, s)
        return mp.sqrt(1 - v * v)

    nodes = sorted({w.start, w.stop, t})
    lo, hi = (w.start, t) if t >= w.start else (t, w.start)
    pieces = [p for p in nodes if lo <= p <= hi]
    total = mp.fsum(mp.quad(rate, [a, b]) for a, b in itertools.pairwise(pieces) if b > a)
    return total if t >= w.start else -total


@at_reference_precision
def material_point(f: float, length: Mp) -> Mp:
    """Rest-frame distance of fraction ``f`` from the left end (the right end exactly ``L``)."""
    return F(f) * length if f != 1.0 else length


# ------------------------------------------------------------------ frame slices
@at_reference_precision
def lab_time(x: OfTime, beta: Mp, t_frame: Mp, solver: SliceSolver = "bisection") -> Mp:
    """The lab time ``t`` where a worldline ``x(t)`` crosses frame time ``t'``: the root of
    ``gamma (t - beta x(t)) = t'``.

    The left side is strictly increasing in ``t`` (|dx/dt| < 1). The root is bracketed by
    quadrupling ``[-1, 1]`` and narrowed until the bracket is below ``10^-(digits - 2)`` of
    its scale, by bisection or by the Anderson-Bjorck secant (which falls back to a
    bisection step whenever an iteration fails to halve the bracket).
    """
    g = gamma_of(beta)

    def f(t: Mp) -> Mp:
        return g * (t - beta * x(t)) - t_frame

    lo, hi = mp.mpf(-1), mp.mpf(1)
    while f(lo) > 0:
        lo *= 4
    while f(hi) < 0:
        hi *= 4
    if solver == "anderson-bjorck":
        return _anderson_bjorck(f, lo, hi, _bracket_tolerance(lo, hi))
    return _bisect(f, lo, hi)


def _bracket_tolerance(lo: Mp, hi: Mp) -> Mp:
    """How narrow a root's bracket gets: ``10^-(digits - 2)`` of its scale."""
    return max(abs(lo), abs(hi), mp.mpf(1)) * mp.mpf(10) ** (-(REFERENCE_DIGITS - 2))


def _bisect(f: Callable[[Mp], Mp], lo: Mp, hi: Mp) -> Mp:
    """The root of increasing ``f`` in ``[lo, hi]`` (``f(lo) <= 0 <= f(hi)``), by bisection to
    :func:`_bracket_tolerance`."""
    tol = _bracket_tolerance(lo, hi)
    while hi - lo > tol:
        mid = (lo + hi) / 2
        if f(mid) < 0:
            lo = mid
        else:
            hi = mid
    return (lo + hi) / 2


@at_reference_precision
def frame_slice(w: Worldline, beta: Mp, t_frame: Mp, solver: SliceSolver = "bisection") -> Mp:
    """x' at frame time t': the lab time ``t`` of :func:`lab_time`, then x' = gamma (x(t) - beta t)."""
    t = lab_time(w.x, beta, t_frame, solver)
    return gamma_of(beta) * (w.x(t) - beta * t)


@at_reference_precision
def frame_slice_and_clock(w: Worldline, beta: Mp, t_frame: Mp, solver: SliceSolver = "bisection") -> tuple[Mp, Mp]:
    """``(x', tau)`` at frame time t': one lab time ``t`` of :func:`lab_time`, then
    ``x' = gamma (x(t) - beta t)`` and the clock ``tau(t)`` (the same in every frame)."""
    t = lab_time(w.x, beta, t_frame, solver)
    return gamma_of(beta) * (w.x(t) - beta * t), w.tau(t)


def _anderson_bjorck(f: Callable[[Mp], Mp], lo: Mp, hi: Mp, tol: Mp) -> Mp:
    """Root of increasing ``f`` in ``[lo, hi]`` (f(lo) <= 0 <= f(hi)) to a bracket below ``tol``."""
    f_lo, f_hi = f(lo), f(hi)
    if f_lo == 0:
        return lo
    if f_hi == 0:
        return hi
    kept = 0  # +1: hi was kept last time, -1: lo was kept
    while hi - lo > tol:
        width = hi - lo
        t = hi - f_hi * (hi - lo) / (f_hi - f_lo)
        if not lo < t < hi:
            t = (lo + hi) / 2
        f_t = f(t)
        if f_t == 0:
            return t
        if f_t < 0:
            if kept == 1:  # hi kept twice: shrink its weight (Anderson-Bjorck)
                m = 1 - f_t / f_lo
                f_hi = f_hi * (m if m > 0 else mp.mpf(0.5))
            lo, f_lo, kept = t, f_t, 1
        else:
            if kept == -1:
                m = 1 - f_t / f_hi
                f_lo = f_lo * (m if m > 0 else mp.mpf(0.5))
            hi, f_hi, kept = t, f_t, -1
        if hi - lo > width / 2:  # no halving: guarantee progress with a bisection step
            mid = (lo + hi) / 2
            f_mid = f(mid)
            if f_mid == 0:
                return mid
            if f_mid < 0:
                lo, f_lo = mid, f_mid
            else:
                hi, f_hi = mid, f_mid
            kept = 0
    return (lo + hi) / 2


@at_reference_precision
def boost_event(e: tuple[Mp, Mp], beta: Mp) -> tuple[Mp, Mp]:
    """``(t', x') = gamma (t - beta x, x - beta t)``."""
    g = gamma_of(beta)
    t, x = e
    return g * (t - beta * x), g * (x - beta * t)


@at_reference_precision
def signal_arrival(w: Worldline, source: tuple[Mp, Mp]) -> tuple[Mp, Mp]:
    """Lab event where a light ray from ``source`` sent toward the point first meets worldline ``w``.

    With ``d = sign(x(t_0) - x_0)`` (the ray's direction) the arrival is the root of
    ``h(t) = (t - t_0) - d (x(t) - x_0)``, which increases with ``t`` (the point is slower than
    light) and is ``<= 0`` at ``t_0``: bracketed by doubling and narrowed by bisection to
    ``10^-(digits - 2)`` of its scale. A source on the worldline is its own arrival.
    """
    t0, x0 = source
    ahead = w.x(t0) - x0
    if ahead == 0:
        return t0, x0
    d = 1 if ahead > 0 else -1

    def h(t: Mp) -> Mp:
        return (t - t0) - d * (w.x(t) - x0)

    step = max(abs(t0), abs(x0), mp.mpf(1))
    lo, hi = t0, t0 + step
    while h(hi) < 0:
        lo, hi = hi, hi + 2 * (hi - t0)
    t = _bisect(h, lo, hi)
    return t, x0 + d * (t - t0)


# ------------------------------------------------------------------ the cases of the committed table
#: The committed table lists its fixed cases group by group; a case's ``order`` is its group
#: plus its position in the group (the random cases follow all fixed ones).
PAPER_EXAMPLES = 100
ULTRA_RELATIVISTIC = 200
HORIZON = 300
"""Near the Rindler horizon (``a'_F L0 -> 1``) and far from it."""
MASS_RATIOS_AND_SIZES = 400
VELOCITY_CHANGES = 500
WEAK_ACCELERATION = 600
"""``a'_F L0 = 1e-3 .. 1e-7``: every point's radius ``rho = 1/a'`` is ``10^3 .. 10^7`` rest lengths,
so clocks advance ``rho`` times the rapidity change, read in frames far from the lab."""
PARADOXES = 700
"""Bell's spaceships and the pole in the barn (Born-rigid and signal-limited stops)."""
SMALL_SPEEDS = 800
"""The paradoxes at ``V = 1e-6`` and ``1e-3``, Bell's string breaking at strains down to ``1e-12``:
``gamma - 1``, ``cosh theta - 1`` and the strain are ``~V^2/2``, lost by any subtraction."""
#: Each group's name in the committed table (``order // 100 * 100`` is a fixed case's group;
#: the random cases form the group ``"random"``).
GROUP_NAMES: Mapping[int, str] = MappingProxyType(
    {
        PAPER_EXAMPLES: "paper",
        ULTRA_RELATIVISTIC: "ultra-relativistic",
        HORIZON: "horizon",
        MASS_RATIOS_AND_SIZES: "mass-ratios-sizes",
        VELOCITY_CHANGES: "velocity-changes",
        WEAK_ACCELERATION: "weak-acceleration",
        PARADOXES: "paradoxes",
        SMALL_SPEEDS: "small-speeds",
    }
)


@dataclass(frozen=True)
class ReferenceCase:
    """One scene of the committed table: its kind, its parameters (floats taken as exact) and its place."""

    kind: str
    params: Parameters
    order: int
    """Sort key of the table's fixed cases (a group above plus a position): the table is
    generated case by case from one random stream (frames and sample times), so the order
    is part of its content."""

    @property
    def group(self) -> str:
        """The name of the case's group (:data:`GROUP_NAMES`)."""
        return GROUP_NAMES[self.order // 100 * 100]


#: How a scene kind draws the parameters of a random case from the table's one random stream.
Draw = Callable[[random.Random], dict[str, float | None]]


@dataclass(frozen=True)
class SceneReference:
    """One scene kind's reference: its 50-digit builder and its cases in the committed table."""

    kind: str
    """The core's name of the scene (``"rod-collision"``); the reference never imports the core."""
    order: int
    """Teaching order (the core's): the random cases choose among the kinds in this order."""
    build: Callable[..., RefScene]
    """``build(fractions, **params)``: the lab worldlines of the material ``fractions`` of each rod."""
    cases: tuple[ReferenceCase, ...] = ()
    draw: Draw | None = None
    """This kind's share of the random cases: parameters drawn from the stream (``None``: none)."""

    def __post_init__(self) -> None:
        for case in self.cases:
            if case.kind != self.kind:
                raise ValueError(f"{self.kind}: a case of {case.kind!r}")


def speed(rng: random.Random) -> float:
    """A random speed: 40% ultra-relativistic ``1 - 10^-k`` (``k`` up to 12), else uniform in (0.01, 0.99)."""
    return 1.0 - 10.0 ** (-rng.uniform(0.05, 12.0)) if rng.random() < 0.4 else rng.uniform(0.01, 0.99)


def log_uniform(rng: random.Random, lo: float, hi: float) -> float:
    """``10^k`` for ``k`` uniform in ``[lo, hi]``."""
    return 10.0 ** rng.uniform(lo, hi)


def discover() -> tuple[SceneReference, ...]:
    """Every :class:`SceneReference` in this package's modules, in teaching order (``order``, then kind)."""
    found: list[SceneReference] = []
    for info in pkgutil.iter_modules(__path__):
        module = importlib.import_module(f"{__name__}.{info.name}")
        found.extend(getattr(module, "SCENES", ()))
    kinds = [r.kind for r in found]
    if len(set(kinds)) != len(kinds):
        raise ValueError(f"a scene kind has two references: {sorted(kinds)}")
    return tuple(sorted(found, key=lambda r: (r.order, r.kind)))


#: Every scene kind's reference, in teaching order (found in this package's modules).
REFERENCES: Mapping[str, SceneReference] = MappingProxyType({r.kind: r for r in discover()})
#: Reference builders by scene kind (the core's names): ``BUILDERS[kind](fractions, **params)``,
#: the first argument the material fractions to follow, the rest the scene's parameters.
BUILDERS: Mapping[str, Callable[..., RefScene]] = MappingProxyType({k: r.build for k, r in REFERENCES.items()})
