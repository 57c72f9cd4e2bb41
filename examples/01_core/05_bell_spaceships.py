"""Bell's spaceships: equal accelerations stretch the string between them; a Born-rigid rod would not.

Two ships start at rest with their rear ends 1 apart (the lab distance ``separation``), each a
short Born-rigid rod of 0.1, and both rear ends accelerate at a = 0.5 until V = 0.6 (c = 1; the
formalism of Franklin 2012, Sec. 3, "Constant acceleration"). The rear ends stay 1 apart in the
lab, so in the ships' frame after they are gamma * 1 = 1.25 apart: the string, unstretched at
s - l = 0.9, ends at a rest length of 1.15 (strain 5/18) and breaks on the way if its breaking
strain is lower. The Born-rigid rod spanning the same points keeps its rest length 1.
"""

import rigidrel_core as rr


def main() -> None:
    scene = rr.bell_spaceships(0.6, 1.0, 0.5, breaking_strain=0.2)
    after = scene.frame("ships after")
    events = scene.events_in(frame=after)
    gap = events["T_B2"][1] - events["T_B1"][1]
    print(f"rear ends in the ships' frame after: {gap:.6f} apart (gamma * separation = 1.25)")
    print(f"string rest length: {scene.string_unstretched:.6f} -> {scene.string_final:.6f}")
    assert scene.string_break is not None  # None: the string holds (strain below its breaking strain)
    t, x = scene.string_break
    print(f"the string breaks at strain 0.2: lab (t, x) = ({t:.6f}, {x:.6f})")
    for note in scene.notes():
        print(note)


if __name__ == "__main__":
    main()
