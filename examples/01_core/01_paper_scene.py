"""Fig. 3 of the paper: one collision, seen from the lab and from the barycentric frame.

Rod 1 (mass M1, V1 = 0.6) hits rod 2 (M2 = 2 M1, at rest) elastically; both rods are one rest
length long (Franklin 2012, Sec. 6; units c = L0 = 1). In the lab the far ends start and stop
changing velocity at T_1 = -3/4, T'_1 = 9/40, T_2 = 0, T'_2 = 39/80. In the barycentric frame
(u = 3/13) the collision is symmetric in time: each far end stops as long after the contact as
it started before it. The rods leave with V'_1 = -9/41 and V'_2 = 39/89.
"""

from fractions import Fraction

import rigidrel_core as rr


def main() -> None:
    scene = rr.build_scene("rod-collision", mass1=1.0, mass2=2.0)  # Fig. 3: the defaults are the paper's
    for name in ("lab", "barycentric"):
        frame = scene.frame(name)
        print(f"events in the {name} frame (beta = {frame.beta:.6f}):")
        for event, (t, x) in scene.events_in(frame=frame).items():
            print(f"  {event:4s}  t = {t:+.6f}  x = {x:+.6f}")
    for rod, v in zip(scene.rods, scene.final_velocities):
        print(f"{rod.name} leaves with V' = {v:+.6f} = {Fraction(v).limit_denominator(100)}")


if __name__ == "__main__":
    main()
