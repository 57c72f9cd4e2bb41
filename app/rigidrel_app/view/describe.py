"""What the canvas shows, in words: for a screen reader, the command line and the exported pages.

Written from the core's numbers, events and verdicts, never from pixels. :func:`describe` gives a
:class:`Description` of a state at one instant of the playback clock: the scene and its parameters,
the two lanes' frames, each lane at the instant (where each rod is, its equal-time length, which of
its ends are accelerating, its clocks), the named events already passed in each lane's frame, and
the causal verdicts. Its :attr:`~Description.summary` is what a tab announces when the scene,
figure, frame or step changes; :attr:`~Description.full` is read on demand (key D).
"""

from __future__ import annotations

from dataclasses import dataclass

import rigidrel_core as rr

from .diagrams import frame_title
from .objects import object_words_at
from .signals import verdict_lines
from .state import Resolved, format_value

#: The rods' two ends, as the core numbers them (0: left, 1: right).
END_NAMES = ("left", "right")


def _number(x: float) -> str:
    """``x`` to three decimals, a rounding-noise -0 shown as 0, a minus as a screen reader says it."""
    return f"{round(float(x), 3) + 0.0:.3f}".replace("-", "minus ")


@dataclass(frozen=True)
class Description:
    """A state at one instant, in sentences."""

    scene: str
    """The scene, its source in the paper and its parameters."""
    frames: str
    """What each lane shows: the lab above, the chosen (or riding) frame below."""
    lanes: tuple[str, ...]
    """Each lane at the instant: its rods, lengths, accelerating ends and clocks."""
    events: tuple[str, ...]
    """The named events already passed, in each lane's frame."""
    verdicts: tuple[str, ...]
    """The core's causal verdicts in words (the lab's)."""

    @property
    def summary(self) -> str:
        """What is announced when the scene, the figure, the frame or the step changes."""
        return f"{self.scene} {self.frames}"

    @property
    def full(self) -> str:
        """Everything, one paragraph per line (key D, ``rigidrel describe``)."""
        return "\n".join((self.scene, self.frames, *self.lanes, *self.events, *self.verdicts))


def _lane(scene: rr.Scene, frame: rr.Frame, now: float, name: str) -> str:
    """One lane at clock time ``now`` (its frame's time): each rod's ends, length, accelerating
    ends and clocks, from the core."""
    x, tau = scene.snapshot(now, frame=frame, fractions=(0.0, 1.0))
    lengths = scene.lengths(now, frame=frame)
    switches = scene.switch_times(frame=frame)
    prime = "" if frame.same_velocity(rr.LAB) and name == "lab" else "′"
    rods = []
    for k, rod in enumerate(scene.rods):
        moving = [END_NAMES[e] for e in range(2) if switches[k, e, 0] <= now < switches[k, e, 1]]
        accel = (
            "both ends accelerating"
            if len(moving) == 2
            else f"its {moving[0]} end accelerating"
            if moving
            else "neither end accelerating"
        )
        rods.append(
            f"{rod.name} from x{prime} = {_number(x[k, 0])} to {_number(x[k, 1])}, length {_number(lengths[k])}, "
            f"{accel}, its clocks reading {_number(tau[k, 0])} (left) and {_number(tau[k, 1])} (right)"
        )
    things = [object_words_at(o, frame, now) for o in scene.objects]  # the door open or closed, the string
    return f"The {name} lane at t{prime} = {_number(now)}: " + "; ".join(rods + [t for t in things if t]) + "."


def _passed(scene: rr.Scene, frame: rr.Frame, now: float, name: str) -> str:
    """The named events at or before clock time ``now`` in ``frame``, in their order there."""
    prime = "" if name == "lab" else "′"
    events = sorted((t, e) for e, (t, _) in scene.events_in(frame=frame).items() if t <= now + 1e-12)
    if not events:
        return f"In the {name} lane no named event has happened yet."
    said = ", ".join(f"{e} at t{prime} = {_number(t)}" for t, e in events)
    return f"Events passed in the {name} lane: {said}."


def describe(resolved: Resolved, now: float, one_lane: bool | None = None) -> Description:
    """``resolved`` at playback time ``now`` (the lab lane's t and the lower lane's t′), in words.
    While the lower lane rides a point, it is described in the frame its second diagram is drawn
    in (the scene's default), and says so. ``one_lane``: the picture shows the lab alone (by
    default where the chosen frame is the lab's own, as the live canvas draws it; an exported
    lesson's lanes show two)."""
    scene, frame = resolved.scene, resolved.frame
    d = rr.describe(scene)
    params = ", ".join(
        f"{d.parameter(k).label} = {format_value(v)}" for k, v in scene.parameters.items() if v is not None
    )
    scene_text = f"{d.title} ({d.source}): {d.summary} Parameters: {params}."
    lower = frame_title(frame)
    ride = ""
    if resolved.ride is not None:
        ride = f" The lower lane rides {resolved.ride.label(scene)}; described here in the {lower} frame."
    if resolved.lab_only if one_lane is None else one_lane:  # one lane: the chosen frame is the lab
        frames_text = "One lane: the lab frame (the frame chosen)."
        lanes, events = (_lane(scene, rr.LAB, now, "lab"),), (_passed(scene, rr.LAB, now, "lab"),)
    else:
        frames_text = f"Upper lane: the lab frame. Lower lane: the {lower} frame.{ride}"
        lanes = (_lane(scene, rr.LAB, now, "lab"), _lane(scene, frame, now, "lower"))
        events = (_passed(scene, rr.LAB, now, "lab"), _passed(scene, frame, now, "lower"))
    verdicts = tuple(f"Causality: {line}" for line in verdict_lines(scene))
    return Description(scene_text, frames_text, lanes, events, verdicts)
