r"""Bell's spaceships: two ships with the same proper acceleration, a string between them.

The paper's introduction cites Bell's spaceships, which its author treated with the constant
acceleration of Sec. 3. Units c = 1. Two ships start at rest at lab ``t = 0``; their rear ends are
a lab distance ``s`` (``separation``) apart, at ``x = 0`` and ``x = s``. Each ship is a short
Born-rigid rod of rest length ``l`` (``ship_length``) whose rear end has the proper acceleration
``a`` (``a_back``, the paper's ``a'_B``); its front end then has ``a / (1 + a l)`` (Sec. 3,
Eq. (15) solved for ``a'_F``). Both rear ends reach ``V`` at the same lab instant
``T_B = gamma V / a`` (Eq. (9)): the lab distance of the rears stays ``s`` throughout, so in the
ships' rest frame after, it is ``gamma s`` (the rear ends' events at lab ``T_B`` are simultaneous
in the lab, not in that frame).

**The string** joins the rear ship's front end (rest-distance ``R = 1/a + l`` from its centre
``C_1 = (0, -1/a)``) to the front ship's rear end (radius ``r = 1/a`` about ``C_2 = (0, s - 1/a)``).
Its proper length at an instant is its rest length in the rear ship's momentarily comoving
frame: while the rear ship is at rapidity ``theta`` (its whole body: it is Born-rigid), that
frame's line of simultaneity through the string's rear end passes through ``C_1``. Boosting
``C_2 - C_1 = (0, s)`` into it gives ``(-s sinh theta, s cosh theta)``, so the front ship's rear
end is met on its hyperbola where ``r sinh(phi - theta) = s sinh theta`` and

.. math::
    D(\theta) = s\cosh\theta + \sqrt{r^2 + s^2\sinh^2\theta}
    \quad(\phi = \theta + \operatorname{asinh}(s \sinh\theta / r) \le \theta_V),

    D(\theta) = \frac{r + s\cosh\theta_V}{\cosh(\theta_V - \theta)}
    \quad\text{(the front ship's rear already coasting)},

is that rear end's distance from ``C_1``; the string is ``D(theta) - r - l`` long: ``s - l`` at
rest, ``gamma s - l`` once both ships coast (``theta = theta_V``), and increasing in between.

**Its strain** is ``(D - r - l)/(s - l) - 1 = E/(s - l)``, with ``E = D - r - s`` the string's
stretch, formed from products so that nothing cancels at small speeds or small strains
(``cosh x - 1 = 2 sinh^2(x/2)``):

.. math::
    E = 2 s \sinh^2\frac{\theta}{2} + \frac{q^2}{\sqrt{r^2 + q^2} + r}
    \quad (q = s \sinh\theta,\ \text{first form}),

    E = \frac{2}{\cosh\delta}\Bigl(s \sinh\bigl(\theta_V - \tfrac{\theta}{2}\bigr) \sinh\frac{\theta}{2}
        - r \sinh^2\frac{\delta}{2}\Bigr) \quad (\delta = \theta_V - \theta,\ \text{second form}),

and ``(gamma - 1) s`` once both coast (``gamma - 1`` from the product ``(gamma V)^2/(gamma + 1)``).
The strain is measured in the **rear ship's momentarily comoving frame** (the string's rear end's):
that is the convention every number of the string depends on. Measured in the front ship's frame
the same strain is reached at another event (later: the front ship accelerates after the rear
ship in that frame's time), so the break event names its frame.

**The break**, given a breaking strain ``e_b``, is where ``E = e_b (s - l)``: on the first form
(``D = r + s + E``, its square solved for ``cosh theta``)

.. math::
    \cosh\theta - 1 = \frac{E (2 r + E)}{2 D s}, \quad
    \theta = 2 \operatorname{asinh}\sqrt{\frac{E (2 r + E)}{4 D s}},

or, where the front ship's rear already coasts, ``cosh delta - 1 = ((gamma - 1) s - E)/D``; the
break event is the string's rear end there, ``C_1 + R (sinh theta, cosh theta)``, i.e. lab
``(R sinh theta, l + 2 R sinh^2(theta/2))`` (Sec. 3, Eq. (4) about ``C_1``, ``R = 1/a + l``).

**The comparison rod** starts between the same two rear ends (lab ``x = 0`` and ``x = s`` at
``t = 0``), rest length ``s``, its rear end moving with the rear ship's (the same rear
acceleration ``a``): Born-rigid, its front end accelerates less, ``a / (1 + a s)`` (Eq. (15)),
and reaches ``V`` later, at ``gamma V (1/a + s)``; it keeps its rest length ``s``, so its front end
falls behind the front ship's rear.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from types import MappingProxyType

import numpy as np
import numpy.typing as npt

from .. import _dd
from .._budget import PhysicalSystem
from .._build import ACCELERATION, SIZE, V, checked_rods, checked_scene, rigid_motion
from .._description import (
    EventDescription,
    Interval,
    ObjectKind,
    OriginEvent,
    Parameter,
    PresetFigure,
    SceneDescription,
    ScenePreset,
    Slider,
    given,
)
from .._exact import REST, ExactVelocity
from .._frame import LAB, Frame, check_frame
from .._objects import MaterialWorldline, ObjectEvent, ObjectField, SceneObject
from .._scene import EventSpec, Rod, Scene
from .._validate import ParameterError, refuse_renamed
from .._words import event_in_words

FloatArray = npt.NDArray[np.float64]

SEPARATION = Parameter(
    "separation",
    "s",
    "s (rear ends apart)",
    "length unit",
    SIZE,
    1.0,
    "lab distance s of the two ships' rear ends (the same at every lab time)",
    Slider(0.1, 10.0, 0.1),
    typical=(0.1, 10.0),
)
A_BACK = Parameter(
    "a_back",
    "a",
    "a (rear ends)",
    "1/length unit",
    ACCELERATION,
    0.5,
    "proper acceleration a = a′_B of each ship's rear (back) end; each stops at lab t = γV/a (Sec. 3, Eq. (9))",
    Slider(0.05, 5.0, 0.05),
    typical=(0.05, 5.0),
)


def default_ship_length(separation: float) -> float:
    """Each ship's rest length when none is given: a tenth of the separation, ``l = s/10``."""
    return 0.1 * separation


SHIP_LENGTH = Parameter(
    "ship_length",
    "l",
    "l (ship)",
    "length unit",
    SIZE,
    None,
    "rest length l of each ship (default none: a tenth of the separation, s/10)",
    Slider(0.01, 1.0, 0.01),
    typical=(0.01, 1.0),
    optional=True,
    constraint="ship_length < separation",
    when_omitted=lambda p: default_ship_length(given(p, "separation")),
)
BREAKING_STRAIN = Parameter(
    "breaking_strain",
    "e_b",
    "breaking strain",
    "",
    Interval(0.0, math.inf),
    0.25,
    "the string's strain (rest length over its unstretched length, minus 1) at which it breaks (none: never)",
    Slider(0.01, 2.0, 0.01),
    typical=(0.01, 2.0),
    optional=True,
)

#: Rods of the scene, in order.
REAR_SHIP, FRONT_SHIP, COMPARISON_ROD = 0, 1, 2
#: The material points the string joins, as ``(rod, fraction)``: the rear ship's front end, the front
#: ship's rear end.
_STRING_ENDS = ((REAR_SHIP, 1.0), (FRONT_SHIP, 0.0))
_EVENTS = (
    EventSpec("T_B1", REAR_SHIP, 0, "stop"),
    EventSpec("T_F1", REAR_SHIP, 1, "stop"),
    EventSpec("T_B2", FRONT_SHIP, 0, "stop"),
    EventSpec("T_F2", FRONT_SHIP, 1, "stop"),
    EventSpec("T_Frod", COMPARISON_ROD, 1, "stop"),
)
FRAMES = ("lab", "ships after")


@dataclass(frozen=True)
class BellString:
    """The string between the ships (module docstring): its geometry and its rear end's worldline, a
    pure value (it holds no scene), so that the scene's string object can carry its strain as a field."""

    separation: float
    ship_length: float
    a_back: float
    """The proper acceleration ``a`` of each ship's rear (back) end, the paper's ``a'_B``."""
    velocity: ExactVelocity
    """The ships' final velocity ``V``."""
    rear_end: MaterialWorldline
    """The string's rear end: the rear ship's front end."""
    breaking_strain: float | None = None

    @property
    def unstretched(self) -> float:
        """The string's rest length at the start, ``s - l``."""
        return self.separation - self.ship_length

    @property
    def final_stretch(self) -> float:
        """How much longer the string ends than it starts, ``(gamma - 1) s`` (``gamma - 1`` a product:
        exact at small ``V``)."""
        return self.velocity.lorentz_factor_minus_one() * self.separation

    @property
    def final(self) -> float:
        """The string's rest length once both ships coast, ``gamma s - l = (s - l) + (gamma - 1) s``."""
        return self.unstretched + self.final_stretch

    @property
    def final_strain(self) -> float:
        """The strain once both ships coast: ``(gamma - 1) s / (s - l)``, measured in the ships'
        common rest frame after (the rear ship's comoving frame then)."""
        return self.final_stretch / self.unstretched

    def stretch_at_rapidity(self, rapidity: npt.ArrayLike) -> FloatArray:
        """The string's stretch ``E = L_string - (s - l)`` when the rear ship has lab rapidity ``theta``
        (clipped to ``[0, theta_V]``), its rest length measured in the rear ship's comoving frame: each
        form of the module docstring from products, without cancellation (``sinh^2`` for ``cosh - 1``,
        ``sqrt(r^2 + q^2) - r = q^2 / (sqrt(r^2 + q^2) + r)``)."""
        return self.separation * self._stretch_per_separation(rapidity)

    def _stretch_per_separation(self, rapidity: npt.ArrayLike) -> FloatArray:
        """``E / s`` at the rear ship's lab rapidity (clipped to ``[0, theta_V]``): the module
        docstring's forms with ``s = 1`` and ``r/s`` for ``r``, so that no product of two lengths
        under- or overflows however small or large the scene."""
        theta_v = self.velocity.rapidity()
        theta = np.clip(np.asarray(rapidity, dtype=np.float64), 0.0, theta_v)
        r = self._radius_per_separation
        q = np.sinh(theta)
        half = np.sinh(0.5 * theta)
        on_hyperbola = 2.0 * half * half + q * q / (np.hypot(r, q) + r)
        delta = theta_v - theta
        half_delta = np.sinh(0.5 * delta)
        coasting = 2.0 * (np.sinh(theta_v - 0.5 * theta) * half - r * half_delta * half_delta) / np.cosh(delta)
        phi = theta + np.arcsinh(q / r)
        return np.where(phi <= theta_v, on_hyperbola, coasting)

    @property
    def _radius_per_separation(self) -> float:
        """``r / s = 1 / (a s)``: the rear ends' Rindler radius in separations."""
        return (1.0 / self.a_back) / self.separation

    def rest_length_at_rapidity(self, rapidity: npt.ArrayLike) -> FloatArray:
        """The string's rest length (in the rear ship's comoving frame) when the rear ship has lab
        rapidity ``theta`` (clipped to ``[0, theta_V]``): ``D(theta) - r - l = (s - l) + E``."""
        return self.unstretched + self.stretch_at_rapidity(rapidity)

    def rapidities(self, t: npt.ArrayLike, *, frame: Frame = LAB) -> FloatArray:
        """The rear ship's lab rapidity when the string's rear end is at frame time ``t'``: that end's
        clock ``tau`` over its radius ``R = 1/a + l`` (proper acceleration ``1/R``), clipped to
        ``[0, theta_V]``; an invariant of the event."""
        tau = self.rear_end.proper_times(t, frame=frame)
        radius = 1.0 / self.a_back + self.ship_length
        return np.clip(tau / radius, 0.0, self.velocity.rapidity())

    def rest_lengths(self, t: npt.ArrayLike, *, frame: Frame = LAB) -> FloatArray:
        """The string's proper length when its rear end is at frame time ``t'``: its rest length in
        the rear ship's momentarily comoving frame. Shape of ``t``."""
        return self.rest_length_at_rapidity(self.rapidities(t, frame=frame))

    def strain_at_rapidity(self, rapidity: npt.ArrayLike) -> FloatArray:
        """``L_string / (s - l) - 1 = E / (s - l)`` when the rear ship has lab rapidity ``theta``
        (clipped to ``[0, theta_V]``), the string's length measured in the rear ship's comoving frame:
        from the stretch ``E`` (module docstring), exact however small the strain."""
        return self._stretch_per_separation(rapidity) * (self.separation / self.unstretched)

    def strains(self, t: npt.ArrayLike, *, frame: Frame = LAB) -> FloatArray:
        """:meth:`strain_at_rapidity` when the string's rear end is at frame time ``t'``."""
        return self.strain_at_rapidity(self.rapidities(t, frame=frame))

    @property
    def break_rapidity(self) -> float | None:
        """The rear ship's lab rapidity where the strain (in its comoving frame) reaches the breaking
        strain, or ``None`` (no breaking strain, or one the string never reaches): the module
        docstring's closed forms, from products."""
        e_b = self.breaking_strain
        if e_b is None or e_b > self.final_strain:
            return None
        # in separations (s = 1, r/s for r): no product of two lengths to under- or overflow
        r = self._radius_per_separation
        theta_v = self.velocity.rapidity()
        stretch = e_b * (self.unstretched / self.separation)
        d = r + 1.0 + stretch
        theta = 2.0 * math.asinh(math.sqrt((stretch / d) * ((2.0 * r + stretch) / 4.0)))
        if theta + math.asinh(math.sinh(theta) / r) > theta_v:  # the front ship's rear coasts there
            rest = max(0.0, self.velocity.lorentz_factor_minus_one() - stretch)
            theta = theta_v - 2.0 * math.asinh(math.sqrt(rest / (2.0 * d)))
        return min(max(theta, 0.0), theta_v)

    @property
    def break_event(self) -> tuple[float, float] | None:
        """Lab ``(t, x)`` of the string's rear end when the strain, measured in the rear ship's
        comoving frame, reaches the breaking strain: ``(R sinh theta, l + 2 R sinh^2(theta/2))``
        (Sec. 3, Eq. (4), ``R = 1/a + l``); ``None`` if it never does."""
        theta = self.break_rapidity
        if theta is None:
            return None
        big_r = 1.0 / self.a_back + self.ship_length
        half = math.sinh(0.5 * theta)
        return (big_r * math.sinh(theta), self.ship_length + 2.0 * big_r * half * half)

    def scene_object(self, front_end: MaterialWorldline) -> SceneObject:
        """The string as a scene object from its rear end to ``front_end`` (the front ship's rear end),
        coloured by its strain from 0 to the breaking strain (or, without one, to the strain it ends at)
        and, if it breaks, in two loose ends from the break event on."""
        breaks = self.breaking_strain is not None
        field = ObjectField(
            "strain",
            self.strains,
            self.breaking_strain if self.breaking_strain is not None else self.final_strain,
            "breaking strain" if breaks else "final strain",
            "breaks" if breaks else "its final",
            percent=True,
            measured_in="in the rear ship's comoving frame",
        )
        lab = self.break_event
        meaning = (
            "the string's strain, measured in the rear ship's comoving frame, reaches the breaking strain: the "
            "event on the string's rear end (where along it it snaps is not modelled)"
        )
        event = None if lab is None else ObjectEvent("break", lab, parts=True, state="broken", meaning=meaning)
        return SceneObject("string", ObjectKind.STRING, (self.rear_end, front_end), field=field, event=event)


@dataclass(frozen=True, eq=False)
class BellScene(Scene):
    """Bell's spaceships (see :mod:`rigidrel_core.scenes.bell`): rods ``0`` the rear ship, ``1`` the
    front ship, ``2`` the Born-rigid comparison rod; the string (its one object) from rod 0's front to
    rod 1's rear."""

    separation: float = 1.0
    ship_length: float = 0.1
    """Each ship's rest length ``l`` (the constructor's default: ``separation / 10``)."""
    a_back: float = 0.5
    """The proper acceleration ``a`` of each ship's rear (back) end, the paper's ``a'_B``."""
    breaking_strain: float | None = None

    @property
    def string(self) -> BellString:
        """The string's geometry and strain (:class:`BellString`)."""
        rear_end = self.objects[0].worldlines[0]
        assert isinstance(rear_end, MaterialWorldline)
        velocity = self.rods[REAR_SHIP].motion.velocity_final
        return BellString(self.separation, self.ship_length, self.a_back, velocity, rear_end, self.breaking_strain)

    @property
    def string_unstretched(self) -> float:
        """The string's rest length at the start, ``s - l``."""
        return self.string.unstretched

    @property
    def string_final(self) -> float:
        """The string's rest length once both ships coast, ``gamma s - l``."""
        return self.string.final

    def string_rest_length_at_rapidity(self, rapidity: npt.ArrayLike) -> FloatArray:
        """:meth:`BellString.rest_length_at_rapidity`."""
        return self.string.rest_length_at_rapidity(rapidity)

    def string_rapidities(self, t: npt.ArrayLike, *, frame: Frame = LAB) -> FloatArray:
        """:meth:`BellString.rapidities`."""
        return self.string.rapidities(t, frame=frame)

    def string_rest_lengths(self, t: npt.ArrayLike, *, frame: Frame = LAB) -> FloatArray:
        """The string's proper length when its rear end is at frame time ``t'``: its rest length in
        the rear ship's momentarily comoving frame. Shape of ``t``."""
        return self.string.rest_lengths(t, frame=frame)

    def string_strains(self, t: npt.ArrayLike, *, frame: Frame = LAB) -> FloatArray:
        """``L_string / (s - l) - 1`` when the string's rear end is at frame time ``t'``, ``L_string``
        measured in the rear ship's momentarily comoving frame (:meth:`BellString.strains`)."""
        return self.string.strains(t, frame=frame)

    @property
    def final_strain(self) -> float:
        """The strain once both ships coast: ``(gamma - 1) s / (s - l)``."""
        return self.string.final_strain

    @property
    def string_break(self) -> tuple[float, float] | None:
        """Lab ``(t, x)`` of the string's rear end when the strain reaches the breaking strain, or
        ``None`` (no breaking strain, or one the string never reaches)."""
        event = self.objects[0].event
        return None if event is None else event.lab

    @property
    def rod_groups(self) -> tuple[int, ...]:
        """The ships (and their string) in group 0; the Born-rigid comparison rod, which spans the same
        two rear ends and touches neither ship, in group 1."""
        return (0, 0, 1)

    @property
    def string_ends(self) -> tuple[tuple[int, float], tuple[int, float]]:
        """The material points the string joins, as ``(rod, fraction)``: its rear end the rear ship's
        front end ``(0, 1.0)``, its front end the front ship's rear end ``(1, 0.0)``."""
        return _STRING_ENDS

    def string_broken(self, t: npt.ArrayLike, *, frame: Frame = LAB) -> npt.NDArray[np.bool_]:
        """Whether the string has broken when its rear end is at frame time ``t'``: ``t' >= t'_b``,
        ``t'_b`` the frame time of the break event :meth:`string_break_in` (its rear end, where the
        strain reaches the breaking strain; the strain grows along that end's worldline, so this is
        the same as ``strain(t') >= e_b``); all ``False`` if it never breaks. Shape of ``t``."""
        return self.objects[0].parted(t, frame=frame)

    @property
    def systems(self) -> tuple[PhysicalSystem, ...]:
        """Two physical systems, never summed: the two ships (and the massless string between them),
        and the Born-rigid rod that starts between the same two rear ends, which stands in their place (a comparison:
        it occupies the ships' places, so it is an alternative to them, not a third body)."""
        m = self.rods[REAR_SHIP].mass_before
        mass = f"{m:g}" + (", the scene's unit (it has no mass option)" if m == 1.0 else "")
        return (
            PhysicalSystem(
                f"the two ships, each of rest mass M = {mass} (the string between them taken as massless)",
                (REAR_SHIP, FRONT_SHIP),
                "drive",
                0.0,
            ),
            PhysicalSystem(
                f"the Born-rigid rod that starts between the same rear ends, given the same rest mass M = {m:g} "
                "(instead of the ships, never beside them)",
                (COMPARISON_ROD,),
                "drive",
                0.0,
            ),
        )

    def notes(self, *, frame: Frame = LAB) -> tuple[str, ...]:
        """The rear ends' distance in the lab and in the ships' frame after, the string's strain and the
        frame it is measured in (the rear ship's comoving frame), and its fate, the break event given
        in ``frame`` (labelled)."""
        frame = check_frame(frame)
        g = self.rods[0].motion.velocity_final.lorentz_factor()
        breaks = self.breaking_strain is not None and self.breaking_strain <= self.final_strain
        lines = [
            f"each ship is a Born-rigid rod of rest length l = {self.ship_length:.6g}, its front end accelerating "
            f"less than its rear, a/(1 + a l); the rear ends stay {self.separation:.6g} apart in the lab; in the "
            f"ships' frame after they are γs = {g * self.separation:.6g} apart",
            "the string's strain is its rest length, measured in the rear ship's momentarily comoving frame, "
            f"over s − l, minus 1: that rest length grows from s − l = {self.string_unstretched:.6g} to γs − l "
            f"= {self.string_final:.6g} (strain {self.final_strain:.4g}){' if the string holds' if breaks else ''}; "
            f"the Born-rigid rod, an alternative to the ships, keeps its rest length {self.separation:.6g}",
        ]
        event = self.string_break_in(frame=frame)
        if self.breaking_strain is None:
            lines.append("no breaking strain given: the string stretches and holds")
        elif event is None:
            lines.append(
                f"the string holds: its strain (in the rear ship's comoving frame) never reaches the breaking "
                f"strain {self.breaking_strain:.4g}"
            )
        else:
            lines.append(
                f"the string's strain, measured in the rear ship's comoving frame (along its line of simultaneity "
                f"through the string's rear end), reaches the breaking strain {self.breaking_strain:.4g} at the "
                f"event {event_in_words(event, frame, 6)} on the string's rear end: the string breaks then (where "
                "along it, the model does not say; measured in the front ship's frame, the same strain is reached "
                "at another event)"
            )
        return tuple(lines)

    def string_break_in(self, *, frame: Frame = LAB) -> tuple[float, float] | None:
        """The break event in ``frame`` (``None`` if the string never breaks)."""
        return self.objects[0].event_in(frame=frame)


def _inverse(a: float) -> _dd.DD:
    return _dd.div((1.0, 0.0), (a, 0.0))


#: The parameters' old names (one name per quantity in every scene: the back end's proper
#: acceleration is ``a_back``, as the front end's is ``a_front``): refused, naming the new ones.
RENAMED = MappingProxyType({"acceleration": "a_back"})


@refuse_renamed(RENAMED)
def bell_spaceships(
    v: float,
    separation: float,
    a_back: float,
    ship_length: float | None = None,
    breaking_strain: float | None = None,
    mass: float = 1.0,
) -> BellScene:
    """Bell's spaceships (module docstring): rear ends at 0 and ``separation``, each with proper
    acceleration ``a_back`` from lab ``t = 0`` until it reaches ``v`` at ``T_B = gamma v / a``
    (Sec. 3, Eq. (9)); ships of rest length ``ship_length`` (default :func:`default_ship_length`,
    ``separation / 10``: the registry, the command line and the app default to it too), Born-rigid
    (front ends at ``a / (1 + a l)``, Eq. (15)); a string from the rear ship's front to the front
    ship's rear, breaking at ``breaking_strain`` if given; and the Born-rigid comparison rod on
    ``[0, separation]`` with the same rear acceleration (its front end at ``a / (1 + a s)``).

    Events: ``"T_B1"``, ``"T_F1"`` (rear ship's rear and front reach ``v``), ``"T_B2"``, ``"T_F2"``
    (front ship's), ``"T_Frod"`` (the comparison rod's front). ``T_B1`` and ``T_B2`` share a lab
    time; in the frame ``"ships after"`` the two rear ends end ``gamma separation`` apart.
    """
    v = V.check(v)
    separation = SEPARATION.check(separation)
    a_back = A_BACK.check(a_back)
    ship = default_ship_length(separation) if ship_length is None else SHIP_LENGTH.check(ship_length)
    if not 0.0 < ship < separation:  # names both: either may be the one to change
        raise ParameterError(
            "parameters", "such that 0 < ship_length < separation", {"separation": separation, "ship_length": ship}
        )
    if not 0.0 < (1.0 / a_back) / separation < math.inf:  # the string's forms take r/s = 1/(a s)
        raise ParameterError(
            "parameters",
            "such that 1/(a_back separation) is a positive finite number",
            {"separation": separation, "a_back": a_back},
        )
    strain = None if breaking_strain is None else BREAKING_STRAIN.check(breaking_strain)
    velocity = ExactVelocity.from_float(v)
    rho = _inverse(a_back)
    rods = (
        Rod("rear ship", rigid_motion(REST, velocity, ship, rho, 0.0), mass, mass),
        Rod("front ship", rigid_motion(REST, velocity, ship, rho, separation), mass, mass),
        Rod("Born-rigid rod", rigid_motion(REST, velocity, separation, rho, 0.0), mass, mass),
    )
    params: dict[str, float] = {"v": v, "separation": separation, "a_back": a_back}
    if ship_length is not None:
        params["ship_length"] = ship
    if strain is not None:
        params["breaking_strain"] = strain
    checked_rods(rods, params)  # before the string is derived from them
    (rear_rod, rear_f), (front_rod, front_f) = _STRING_ENDS
    rear_end = MaterialWorldline(rear_rod, rear_f, rods[rear_rod].motion)
    front_end = MaterialWorldline(front_rod, front_f, rods[front_rod].motion)
    string = BellString(separation, ship, a_back, rods[REAR_SHIP].motion.velocity_final, rear_end, strain)
    frames: Mapping[str, Frame] = MappingProxyType({"lab": LAB, "ships after": Frame(velocity, "ships after")})
    scene = BellScene(
        kind=BELL_SPACESHIPS.kind,
        parameters=MappingProxyType(params),
        rods=rods,
        event_specs=_EVENTS,
        frames=frames,
        external_source="drive",
        heat=0.0,
        origin_event=OriginEvent.START,
        objects=(string.scene_object(front_end),),
        separation=separation,
        ship_length=ship,
        a_back=a_back,
        breaking_strain=strain,
    )
    checked_scene(scene)
    return scene


def _figure_caption(scene: Scene) -> str:
    """The print figure's caption (:class:`~rigidrel_core.PresetFigure`): the ships solid, the
    Born-rigid rod dashed; every number the scene's."""
    assert isinstance(scene, BellScene)
    s, a = scene.separation, scene.a_back
    v = scene.rods[REAR_SHIP].motion.velocity_final
    t_b = scene.events["T_B1"][0]
    broken = scene.string_break
    if broken is not None:
        fate = (
            f"at breaking strain {scene.breaking_strain:g} (measured in the rear ship's comoving frame) it breaks "
            f"at (lab t, x) = ({broken[0]:.4g}, {broken[1]:.4g})"
        )
    else:
        fate = "it holds"
    return (
        f"Bell's spaceships: two ships (solid) whose rear ends have the same proper acceleration a = {a:g} start "
        f"{s:g} apart and reach V = {v.value:g} at the same lab time, T_B1 and T_B2 (t = γV/a = {t_b:.4g}): their "
        f"rear ends stay {s:g} apart in the lab and end γs = {v.lorentz_factor() * s:.4g} apart in the ships' frame. "
        f"The string from the rear ship's front to the front ship's rear {'would stretch' if broken else 'stretches'} "
        f"from rest length {scene.string_unstretched:.4g} to {scene.string_final:.4g} (strain "
        f"{scene.final_strain:.3g}){' if it held' if broken else ''}: {fate}. The Born-rigid rod that starts between "
        f"the same rear ends, its rear end with the rear ship's (dashed, drawn instead of the ships), keeps its rest "
        f"length {s:g}: its front accelerates less, a/(1 + a s) (Eq. (15)), falls behind the front ship and reaches "
        "V only at T_Frod."
    )


#: The print figure of the first preset: the lab diagram with the rear ends' stops, the rod's front
#: end's and the break.
_FIGURE = PresetFigure(
    "bell-spaceships",
    (-0.3, 2.6),
    (("T_B1", "right"), ("T_B2", "left"), ("T_Frod", "left"), ("break", "right")),
    _figure_caption,
)

BELL_SPACESHIPS = SceneDescription(
    kind="bell-spaceships",
    title="Bell's spaceships",
    summary=(
        "Two ships whose rear ends have the same proper acceleration stay a lab distance s apart; the string "
        "between them, its length measured in the rear ship's comoving frame, stretches towards γs − l (and "
        "breaks before it gets there if its breaking strain is lower). A Born-rigid rod that starts between "
        "the same rear ends, instead of the ships, its rear end moving with the rear ship's, keeps its rest "
        "length: its front accelerates less and falls behind the front ship."
    ),
    source="Sec. 1; Sec. 3",
    constructor=bell_spaceships,
    parameters=(V, SEPARATION, A_BACK, SHIP_LENGTH, BREAKING_STRAIN),
    frames=FRAMES,
    default_frame="ships after",
    events=(
        EventDescription(
            "T_B1", "the rear ship's rear (left) end reaches its final velocity (lab V)", "Sec. 3, Eq. (9)"
        ),
        EventDescription(
            "T_F1",
            "the rear ship's front (right) end, the string's rear end, reaches its final velocity",
            "Sec. 3, Eq. (9)",
        ),
        EventDescription(
            "T_B2",
            "the front ship's rear (left) end reaches its final velocity, at the lab time of T_B1",
            "Sec. 3, Eq. (9)",
        ),
        EventDescription("T_F2", "the front ship's front (right) end reaches its final velocity", "Sec. 3, Eq. (9)"),
        EventDescription(
            "T_Frod",
            "the Born-rigid rod's front (right) end reaches its final velocity (it accelerates less)",
            "Sec. 3, Eqs. (9), (15)",
        ),
    ),
    objects=(ObjectKind.STRING,),
    presets=(
        ScenePreset(
            "Bell's spaceships, V = 0.6",
            {"v": 0.6, "separation": 1.0, "a_back": 0.5},
            frame="ships after",
            figure=_FIGURE,
        ),
        ScenePreset(
            "Bell's spaceships: the string breaks at 10% strain",
            {"v": 0.6, "separation": 1.0, "a_back": 0.5, "breaking_strain": 0.1},
        ),
        ScenePreset(
            "Bell's spaceships: a string that holds",
            {"v": 0.6, "separation": 1.0, "a_back": 0.5, "breaking_strain": 1.0},
        ),
    ),
    meanings=MappingProxyType({"v": "final speed V (c = 1) of both ships, which start at rest"}),
    order=60,
    renamed=RENAMED,
)

SCENES = (BELL_SPACESHIPS,)
