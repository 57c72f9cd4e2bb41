"""What a typed or dragged number means: the rules behind the app's number boxes and sliders.

A :class:`NumberEntry` says where a number may go (the control's range: what the app
accepts), how its slider moves over it (linearly, or over ``log10`` of it for a parameter
whose ``Slider.scale`` is ``"log"``, such as a mass ratio, whose box still shows and takes
the number itself: 2, not 0.30103), and how to read what a person typed or dragged. Every
reading is a :class:`Verdict`: a value to use, text still on its way to a number, a refusal
with its notice, or the browser box's own correction of a refused value to undo.

Pure: no viser here, so every rule is tested without a browser.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from typing import Literal

import rigidrel_core as rr

Scale = Literal["linear", "log"]

#: Significant digits a log slider's values are rounded to at least (2.00, not 1.99526).
LOG_DIGITS = 3


@dataclass(frozen=True)
class Use:
    """A legal value: act on it."""

    value: float


@dataclass(frozen=True)
class Typing:
    """Text on its way to a number (``""``, ``"-"``, ``"1e"``, ``"1/"``): nothing to use or refuse yet."""


@dataclass(frozen=True)
class Refuse:
    """A refused value: show ``notice`` (it replaces any older one)."""

    notice: str
    put_back: bool = True
    """Put the control back on the session's value. False leaves what a person typed on screen: a
    box that is put back while someone types into it would mix their next keystrokes with the
    old value (typing 0.5 where 0 is refused would give 0.65)."""


Verdict = Use | Typing | Refuse


def refusal(label: str, shown: str, allowed: str, why: str = "") -> str:
    """The notice for a refused value: it names the control, the value, and what it must be."""
    because = f"{why}; " if why else ""
    return f"{label} = {shown} refused: {because}it must be {allowed}. The last valid scene stays on screen."


_SIGN = "+\\-\u2212"  # + - and the minus sign a slide may have
_PLAIN = rf"[{_SIGN}]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][{_SIGN}]?\d+)?"
_NUMBER = re.compile(rf"^({_PLAIN})$")
_FRACTION = re.compile(rf"^({_PLAIN})\s*/\s*({_PLAIN})$")
_ON_THE_WAY = re.compile(rf"^(?:[{_SIGN}]?\d*\.?\d*(?:[eE][{_SIGN}]?)?|{_PLAIN}\s*/\s*[{_SIGN}]?)$")


def _plain(text: str) -> float:
    return float(text.replace("\u2212", "-"))


def read_number(text: str) -> float | Typing | str:
    """What a person typed: a number (``2``, ``0.01``, ``1e2``, ``−0.5``, ``1/3``), :class:`Typing`
    for text still on its way to one, or why it is none (a sentence fragment for the notice)."""
    t = text.strip()
    if m := _NUMBER.match(t):
        x = _plain(m.group(1))
    elif m := _FRACTION.match(t):
        num, den = _plain(m.group(1)), _plain(m.group(2))
        if den == 0.0:
            return "a fraction needs a denominator other than 0"
        x = num / den
    elif _ON_THE_WAY.match(t):
        return Typing()
    elif "," in t:
        return "not a number (write a decimal point: 0.5, not 0,5)"
    else:
        return "not a number"
    return x if math.isfinite(x) else "not a finite number"


def significant(x: float, digits: int) -> float:
    """``x`` rounded to ``digits`` significant digits."""
    return float(f"{x:.{digits}g}")


def control_value(parameter: rr.Parameter, value: float | None) -> float:
    """What a parameter's slider or box holds: its value, or for an omitted optional one (``None``,
    e.g. the impulsive limit) its default, else its slider's upper end."""
    if value is not None:
        return value
    if parameter.default is not None:
        return float(parameter.default)
    return parameter.slider.hi if parameter.slider is not None else 0.0


@dataclass(frozen=True)
class NumberEntry:
    """One number a person sets with a slider and a box: its label, range and slider scale."""

    label: str
    lo: float
    hi: float
    step: float
    """The slider's step (in decades for a log slider)."""
    scale: Scale = "linear"
    noun: str = "a number"
    """What the notice says the value must be: ``"a number"``, ``"a time"``."""

    def __post_init__(self) -> None:
        if not (self.lo < self.hi and self.step > 0) or (self.scale == "log" and self.lo <= 0):
            raise ValueError(f"bad number entry {self}")

    @classmethod
    def of(cls, parameter: rr.Parameter) -> NumberEntry:
        """A scene parameter's entry: its label and its slider's range and scale (the app accepts
        the slider's range; the core and the command line may accept more)."""
        s = parameter.slider
        if s is None:
            raise ValueError(f"parameter {parameter.name!r} has no slider")
        return cls(parameter.label, s.lo, s.hi, s.step, s.scale)

    # ------------------------------------------------------------------ what it says
    def allowed(self) -> str:
        """``"a number in [0.01, 100]"``."""
        return f"{self.noun} in [{self.lo:g}, {self.hi:g}]"

    def text(self, value: float) -> str:
        """A value as its box shows it: ``"2"``, ``"0.01"``, ``"100"``, ``"0.6"``."""
        return f"{value + 0.0:.6g}"

    def refuse(self, shown: str, why: str = "", put_back: bool = True) -> Refuse:
        return Refuse(refusal(self.label, shown, self.allowed(), why), put_back)

    # ------------------------------------------------------------------ the slider
    @property
    def is_log(self) -> bool:
        return self.scale == "log"

    @property
    def slider_range(self) -> tuple[float, float]:
        """The slider's ends: the range itself, or ``log10`` of it."""
        return (math.log10(self.lo), math.log10(self.hi)) if self.is_log else (self.lo, self.hi)

    def to_slider(self, value: float) -> float:
        """Where ``value`` sits on the slider."""
        return math.log10(value) if self.is_log else value

    def from_slider(self, position: float) -> float:
        """The value at a slider position; a log slider's is rounded to the digits its step can tell
        apart (10**0.30 is 2.00, not 1.99526)."""
        if not self.is_log:
            return position
        digits = max(LOG_DIGITS, math.ceil(-math.log10(self.step * math.log(10.0))) + 1)
        return min(max(significant(10.0**position, digits), self.lo), self.hi)

    def slider_marks(self) -> tuple[tuple[float, str], ...] | None:
        """A log slider's marks: every power of ten in range, labelled as the value (0.01 ... 100).
        ``None``: the slider's own (its two ends)."""
        if not self.is_log:
            return None
        lo, hi = self.slider_range
        return tuple((float(k), f"{10.0**k:g}") for k in range(math.ceil(lo - 1e-9), math.floor(hi + 1e-9) + 1))

    def shows(self, position: float, value: float) -> bool:
        """Whether the slider at ``position`` already shows ``value`` (then it need not be moved)."""
        return math.isfinite(position) and self.from_slider(position) == value

    # ------------------------------------------------------------------ reading
    def read(self, text: object) -> Verdict:
        """What was typed into the box: the box keeps refused text on screen (never put back)."""
        if not isinstance(text, str):
            return self.refuse(repr(text), "not a number", put_back=True)
        x = read_number(text)
        if isinstance(x, Typing):
            return x
        shown = text.strip()
        if isinstance(x, str):
            return self.refuse(repr(shown), x, put_back=False)
        if not self.lo <= x <= self.hi:
            return self.refuse(shown, put_back=False)
        return Use(x)

    def judge_position(self, position: object) -> Verdict:
        """A slider's value, as dragged (nobody types into a slider: its own number box is hidden, and
        the control's text box above it takes typed numbers, :meth:`read`). A position beyond the
        slider's ends, or no number at all, comes from no person: refused and put back."""
        lo, hi = self.slider_range
        if isinstance(position, bool) or not isinstance(position, int | float) or not math.isfinite(position):
            return self.refuse(repr(position))
        x = float(position)
        if lo - 1e-12 <= x <= hi + 1e-12:
            return Use(self.from_slider(min(max(x, lo), hi)))
        return self.refuse(f"10^{x:g}" if self.is_log else repr(x))
