"""One tab's state as a frozen value, and the pure transitions its controls, keys and lesson ask for.

No viser here: a :class:`TabState` is what the tab shows, and every method returns the state a
change leads to. The session (:mod:`.session`) takes it, and the controls
(:meth:`~rigidrel_app.live.controls.Controls.show`), the painter (:mod:`.painter`) and the
caption band show it. The notebook's :class:`~rigidrel_app.notebook.live_state.LiveState` is the
same idea for a notebook cell; the two share the refusal rule (a value the core refuses leaves
the last valid scene on screen and says why, :class:`~rigidrel_app.view.notice.Notice`).
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

from ..lessons.tour import Arrival, locked_changes
from ..view.notice import Notice, Place
from ..view.scenario import Scenario, ScenarioError, parse_scenario
from ..view.state import Settings, beta_problem
from ..view.vocabulary import Shade
from .playback import Playback

#: What the scenario box also accepts in front of a scenario string (copied from a command line).
SERVE_PREFIXES = ("rigidrel serve ", "serve ")


def scenario_problem(exc: ScenarioError) -> str:
    """A scenario string's mistake, led by the flag at fault (``--v1: v1 must be ... in (-1, 1); got 1.6``)."""
    text, flag = str(exc), f"--{exc.parameter}"
    return text if exc.parameter == "scene" or text.startswith(flag) else f"{flag}: {text}"


def read_scenario(text: str) -> Scenario | str:
    """The state a scenario box's ``text`` names (as ``rigidrel serve SCENE ...`` takes it, that
    prefix allowed), or why it names none: the flag at fault and what it allows."""
    line = text.strip()
    for prefix in SERVE_PREFIXES:
        line = line.removeprefix(prefix)
    try:
        scenario = parse_scenario(line)
    except ScenarioError as exc:
        return f"Scenario refused: {scenario_problem(exc)}"
    problem = beta_problem(scenario.settings)
    return scenario if problem is None else f"Scenario refused: {problem}"


@dataclass(frozen=True)
class TabState:
    """What one tab shows: the settings asked for and on screen, the playback clock, the notice, the
    look, and where it is in a lesson."""

    settings: Settings
    """The settings the controls show: the last ones asked for, a refused one too (so the lecturer
    sees what was asked and the notice why it is not on screen)."""
    playback: Playback
    shown: Settings | None = None
    """The settings of the picture on screen (the last valid ones); None before the first picture."""
    notice: Notice = field(default_factory=Notice)
    """Why the last value was refused (its text empty if it was not)."""
    shade: Shade = "light"
    """The theme: light, or the dark projector theme (key T)."""
    presenter: bool = False
    """Presenter mode (key F): the control panel minimized, larger text and thicker lines."""
    zoomed: bool = False
    """One Minkowski diagram over the whole canvas, drawn larger (key Z; Z again: the page back)."""
    caption_shown: bool = True
    """The lesson's caption band over the lanes (key C hides it)."""
    step: int = 0
    """The lesson's step the tab shows (from 0; 0 without a lesson)."""
    locked: frozenset[str] = frozenset()
    """The controls the step fixes: parameter names and any of ``scene``, ``frame``, ``time``."""
    step_window: tuple[str, tuple[float, float]] | None = None
    """The step's scene and its time window: the playback window while that scene shows."""
    lecturer: bool = False
    """The tab was opened at the lecturer's lead address (``--follow``): it may lead the others."""
    still: bool = False
    """The browser asks for reduced motion: a lesson's step does not play by itself."""

    @classmethod
    def opening(cls, settings: Settings, shade: Shade = "light") -> TabState:
        """A new tab: ``settings`` asked for, nothing on screen yet, paused at the origin."""
        return cls(settings, Playback.start((-1.0, 1.0)), shade=shade)

    # ------------------------------------------------------------------ the scene
    def asked(self, new: Settings, problem: str | None = None, place: Place = "scene") -> TabState:
        """``new`` asked for: with no ``problem`` the notice goes; with one, ``new`` is what the
        controls show while the notice says why the picture keeps the last valid scene."""
        return replace(self, settings=new, notice=Notice(problem or "", place))

    def showing(self, shown: Settings, window: tuple[float, float]) -> TabState:
        """The picture is ``shown`` now, whose scene plays over ``window``; the lesson's step
        window replaces it while the step's scene is on screen. The clock stays where it was if
        the window holds it."""
        if self.step_window is not None and self.step_window[0] == shown.scene:
            window = self.step_window[1]
        return replace(self, shown=shown, playback=self.playback.with_window(window))

    def locks_against(self, new: Settings, time: bool = False) -> tuple[str, ...]:
        """The controls the step locks that ``new`` (and a new time, if ``time``) would change."""
        return locked_changes(self.locked, self.settings, new) + (("time",) if time and "time" in self.locked else ())

    def refused(self, text: str, place: Place = "scene") -> TabState:
        """The notice ``text`` in folder ``place`` (it replaces any older one); nothing else changes."""
        return replace(self, notice=Notice(text, place))

    # ------------------------------------------------------------------ the clock
    def with_playback(self, playback: Playback) -> TabState:
        return replace(self, playback=playback)

    def step_start(self, arrival: Arrival) -> Playback:
        """The clock where a lesson's step opens: at its start (else the usual start of the window),
        playing if the step plays by itself (unless the browser asks for reduced motion)."""
        p = self.playback
        p = p.seek(arrival.start) if arrival.start is not None else replace(p, now=Playback.start(p.window).now)
        return replace(p, playing=arrival.autoplay and not self.still)

    # ------------------------------------------------------------------ the look
    def with_shade(self, shade: Shade) -> TabState:
        return replace(self, shade=shade)

    def with_presenter(self, on: bool) -> TabState:
        return replace(self, presenter=on)

    def with_zoomed(self, on: bool) -> TabState:
        return replace(self, zoomed=on)

    def with_caption(self, shown: bool) -> TabState:
        return replace(self, caption_shown=shown)

    # ------------------------------------------------------------------ a lesson
    def as_lecturer(self) -> TabState:
        return replace(self, lecturer=True)

    def arriving(self, index: int, arrival: Arrival) -> TabState:
        """At a lesson's step ``index``: its locks and window (its settings are asked next)."""
        window = (arrival.settings.scene, arrival.window) if arrival.window is not None else None
        return replace(self, step=index, locked=arrival.locked, step_window=window)
