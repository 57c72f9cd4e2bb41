"""A tab moving through its lesson: going to a step, arriving at it, the leading tab's preview, and
the lead (key L). What a step holds is the lesson part's (:mod:`.lesson_part`); a tab without a
lesson has no step to go to, and nothing here asks whether it has one.
"""

from __future__ import annotations

from typing import Protocol

from .playback import Playback
from .tab import Tab


class LessonHooks(Protocol):
    """What a tab giving a lesson tells the server (:class:`~rigidrel_app.live.server.App`)."""

    def step_changed(self, session: Tab, index: int) -> None:
        """This tab went to step ``index`` (with ``--follow``, the leading tab's step is followed)."""
        ...

    def lead(self, session: Tab) -> str | None:
        """This tab asks to lead (key L): None if it leads now (or nothing follows), else why not."""
        ...

    def lecturer(self, session: Tab, token: str) -> bool:
        """This tab's address carried the lead ``token``: True if it is the lecturer's (it leads)."""
        ...


class LessonSteps:
    """The steps of ``tab``'s lesson, as the tab moves through them."""

    def __init__(self, tab: Tab) -> None:
        self.tab = tab

    def go_to(self, index: int, report: bool = True) -> None:
        """Show step ``index`` (kept inside the lesson); ``report``: tell the server (a tab's own
        moves are reported, the leading tab's steps passed on by the server are not)."""
        tab = self.tab
        with tab.lock:
            step = tab.lesson.step(index)
            if step is None or tab.closed:
                return
            moved = step != tab.state.step
            with tab.client.atomic():
                self.arrive(step)
        if moved and report:
            tab.lesson.changed_step(step)

    def arrive(self, index: int) -> None:
        """Arrive at step ``index``: its settings, window, start, autoplay, locks and caption. The
        step's page is the one shared by every tab that shows it on a canvas of this size (the
        leading tab's, its followers', a tab walking the lesson alone): made once, and sent whole
        under a root of its own, so the canvas never shows the old step's lines or words beside
        the new one's (a tab's own picture is updated node by node)."""
        tab = self.tab
        a = tab.lesson.arrival(index)
        tab.state = tab.state.arriving(index, a)
        tab.ask(a.settings, refit=True, shared=True, draw=False)
        tab.set_playback(tab.state.step_start(a))
        tab.show(tab.state)
        tab.draw_now(force_plots=True)

    def preview(self, index: int) -> None:
        """The picture of step ``index`` that the leading tab chose, before anything else of it: the
        page and first instant shared by every tab on a canvas of this size, and the caption (the
        rest follows with :meth:`go_to`). Only with a runtime ready."""
        tab = self.tab
        with tab.lock:
            step = tab.lesson.step(index)
            if step is None or tab.closed or not tab.player.ready:
                return
            a = tab.lesson.arrival(step)
            painting = tab.painter.paint_settings(a.settings, tab.state)
            if painting is None:
                return  # a step that makes no scene: go_to says so
            clock = tab.state.playback.with_window(a.window or painting.drawn.window)
            now = (clock.seek(a.start) if a.start is not None else Playback.start(clock.window)).now
            with tab.client.atomic():
                tab.painter.preview(painting, now)
                tab.words.caption(tab.lesson.caption(tab.state, step))
        tab.client.flush()

    def lead(self) -> None:
        """Key L or the Lead button: the lecturer's tab leads; any other is told why not."""
        tab = self.tab
        refusal = tab.lesson.lead()
        if refusal is not None:
            tab.show(tab.state.refused(refusal, "lesson"))

    def show_leader(self, leads: bool | None) -> None:
        """Who leads, in the Lesson folder (``None``: no tab leads)."""
        tab = self.tab
        with tab.lock:
            if not tab.closed:
                tab.controls.show_leader(leads, tab.state.lecturer)
