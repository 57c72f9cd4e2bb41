"""A new scene in a few lines: describe it, register it, build it by name.

A rod at rest on [0, L0] is kicked at its right end, which jumps to -V: Sec. 4's impulsive
start, mirrored. Its constructor reuses ``rr.velocity_change`` (V_i = 0, V_f = -V, no a'_F: the
impulsive limit); its description borrows parameters, frames and events from the built-in
scenes. Once registered, the app, the command line and the tests find it by name, and a scene
built through the registry names its own description (its kind and parameters are this one's).
"""

import rigidrel_core as rr

KIND = "kick-from-the-right"


def kick_from_the_right(v: float, length: float, mass: float = 1.0) -> rr.Scene:
    """The right end of a rod at rest on [0, length] jumps to velocity -v at t = 0."""
    return rr.velocity_change(0.0, -v, length, None, mass)


def kick_description() -> rr.SceneDescription:
    change = rr.describe("velocity-change")
    return rr.SceneDescription(
        kind=KIND,
        title="Kick from the right",
        summary="A rod at rest is kicked at its right end, which jumps to −V.",
        source="Sec. 4",
        constructor=kick_from_the_right,
        parameters=(
            rr.describe("impulsive-start").parameter("v"),
            change.parameter("length"),
            change.parameter("mass"),
        ),
        frames=change.frames,
        default_frame="rod after",
        events=change.events,
        order=35,
    )


def number(x: float) -> str:
    """``x`` to 6 decimals, with rounding noise such as -1e-16 shown as +0.000000."""
    return f"{round(x, 9) + 0.0:+.6f}"


def main() -> None:
    description = rr.register_scene(kick_description())
    scene = rr.build_scene(KIND, v=0.6)  # length and mass take their defaults, 1
    assert scene.kind == KIND and rr.describe(scene) is description
    print(f"{description.title}: final velocity {scene.final_velocities[0]:+.6f}")
    rest = rr.default_frame(scene)
    print(f"events in the lab and in the {rest.name} frame:")
    lab, after = scene.events, scene.events_in(frame=rest)
    for name, (t, x) in lab.items():
        print(f"  {name:4s}  lab t = {number(t)} x = {number(x)}   {rest.name} t' = {number(after[name][0])}")
        print(f"        ({description.event(name).meaning})")


if __name__ == "__main__":
    main()
