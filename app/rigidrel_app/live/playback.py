"""The playback clock: a pure value that knows where playback is and how it moves on."""

from __future__ import annotations

from dataclasses import dataclass, replace

#: The whole time window plays in this many wall seconds at speed 1.
PLAY_SECONDS = 8.0
#: Frames per wall second while playing (the server's animation rate): one step with the arrow keys.
FRAME_RATE = 40.0


@dataclass(frozen=True)
class Playback:
    """One playback clock ``now`` inside a time ``window`` (the lab lane shows t = now, the frame
    lane t' = now). Every method returns a new value; nothing here draws."""

    window: tuple[float, float]
    now: float
    playing: bool = False
    speed: float = 1.0
    """Multiple of the normal pace (the window in :data:`PLAY_SECONDS` wall seconds)."""
    loop: bool = True

    @classmethod
    def start(cls, window: tuple[float, float]) -> Playback:
        """Paused at the origin (every scene's key event), or at the window's start if 0 is outside it."""
        return cls(window, min(max(0.0, window[0]), window[1]))

    def advance(self, dt: float) -> Playback:
        """``dt`` wall seconds later: playing moves ``now`` on; at the end it loops, or stops exactly
        at the window's end."""
        if not self.playing or dt <= 0.0:
            return self
        t0, t1 = self.window
        now = self.now + dt * self.speed * (t1 - t0) / PLAY_SECONDS
        if now <= t1:
            return replace(self, now=now)
        if self.loop and t1 > t0:
            return replace(self, now=t0 + (now - t1) % (t1 - t0))
        return replace(self, now=t1, playing=False)

    def toggled(self) -> Playback:
        """Play if paused (from the start again if at the end), pause if playing."""
        if self.playing:
            return replace(self, playing=False)
        now = self.window[0] if self.now >= self.window[1] else self.now
        return replace(self, now=now, playing=True)

    def seek(self, now: float) -> Playback:
        """Paused at ``now`` (clamped into the window)."""
        return replace(self, now=min(max(now, self.window[0]), self.window[1]), playing=False)

    def stepped(self, frames: int) -> Playback:
        """Paused ``frames`` frames later (earlier if negative): as far as playing at this speed moves
        in ``frames`` / :data:`FRAME_RATE` wall seconds, clamped into the window."""
        t0, t1 = self.window
        return self.seek(self.now + frames * self.speed * (t1 - t0) / (PLAY_SECONDS * FRAME_RATE))

    def to_event(self, times: tuple[float, ...], direction: int) -> Playback:
        """Paused at the first of ``times`` (sorted) after the clock (``direction`` 1) or before it
        (-1), inside the window; where it is if there is none. A time within 1e-9 of the window's
        span of the clock counts as the clock's own (a key pressed again moves on)."""
        t0, t1 = self.window
        near = 1e-9 * max(t1 - t0, 1e-300)
        inside = [t for t in times if t0 <= t <= t1]
        after = (
            [t for t in inside if t > self.now + near] if direction > 0 else [t for t in inside if t < self.now - near]
        )
        if not after:
            return replace(self, playing=False)
        return self.seek(after[0] if direction > 0 else after[-1])

    def with_window(self, window: tuple[float, float]) -> Playback:
        """Another scene's window; ``now`` stays where it was if the window holds it."""
        return replace(self, window=window, now=min(max(self.now, window[0]), window[1]))
