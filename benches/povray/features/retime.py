#!/usr/bin/env python3
"""Times again, alone, each POV-Ray setting of adaptive.py against our setting that matched its
error in the last sweep (docs/PERFORMANCE.md), interleaved pair by pair, more rounds: the
sweep's ratios move with the machine's load, and this says by how much. The errors need no
new run (the pictures are the sweep's, bit for bit).

    /tmp/aa/bin/python benches/povray/features/retime.py PATH/TO/cga-trace [--rounds 5]
"""

import argparse
import os
import statistics
import tempfile

import adaptive as A

AM2, AM1 = ["+A0.3", "+AM2", "+R3"], ["+A0.3", "+AM1", "+R3", "+J"]
# (scene, POV-Ray flags, our --spp, our (threshold, method)): the sweep's winners.
PAIRS = [
    ("lens", AM2, 4, (0.3, "corners+b16")),
    ("lens", AM1, 4, (0.3, "corners+b8")),
    ("textures", AM2, 16, (0.2, "corners")),
    ("textures", AM1, 16, (0.3, "corners")),
    ("area", AM2, 64, (0.3, "corners")),
    ("area", AM1, 4, (0.5, "corners")),
    ("glass", AM2, 16, (0.4, "corners")),
    ("glass", AM1, 16, (0.5, "corners")),
    ("glassarea", AM2, 16, (0.4, "corners")),
    ("glassarea", AM1, 4, (0.5, "corners")),
    ("mesh", AM2, 16, (0.1, "corners")),
    ("mesh", AM1, 16, (0.4, "corners")),
]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("binary", help="the cga-trace binary")
    ap.add_argument("--rounds", type=int, default=5)
    args = ap.parse_args()
    binary = os.path.realpath(args.binary)
    times = [([], []) for _ in PAIRS]
    with tempfile.TemporaryDirectory() as out:
        A.mesh_include(out)
        for _ in range(args.rounds):
            for (scene, flags, spp, setting), (pov, ours) in zip(PAIRS, times):
                pov.append(A.cpu_run(A.pov_cmd(scene, f"{out}/p.png", 320, 240, flags)))
                ours.append(A.cpu_run(A.ours_cmd(binary, scene, f"{out}/o.png", 320, 240, spp, setting)))
    print(f"machine: {A.machine()}; 320x240, one thread each, CPU time, {args.rounds} rounds interleaved pair by pair")
    print(f"{'scene':10} {'POV-Ray':19} {'CPU s':>6} {'(min-max)':>13}   {'ours':34} {'CPU s':>6} {'(min-max)':>13} {'POV/ours':>9}")
    for (scene, flags, spp, setting), (pov, ours) in zip(PAIRS, times):
        p, o = statistics.median(pov), statistics.median(ours)
        ours_name = " ".join([f"--spp {spp}", *A.adaptive_flags(setting)]).replace("--adaptive-method ", "")
        print(f"{scene:10} {' '.join(flags):19} {p:6.3f} {min(pov):6.3f}-{max(pov):<6.3f}   {ours_name:34} "
              f"{o:6.3f} {min(ours):6.3f}-{max(ours):<6.3f} {p / o:9.2f}")


if __name__ == "__main__":
    main()
