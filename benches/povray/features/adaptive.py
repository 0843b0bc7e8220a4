#!/usr/bin/env python3
"""cga-trace's adaptive anti-aliasing (--spp N --adaptive T, by samples with --adaptive-min M or by corners with
--adaptive-method corners) against POV-Ray 3.7's (+A0.3), at equal measured error, in CPU time (user + sys, one
thread each, medians of interleaved rounds).

Needs numpy and pillow:
    python3 -m venv /tmp/aa && /tmp/aa/bin/pip install numpy pillow
    /tmp/aa/bin/python benches/povray/features/adaptive.py PATH/TO/cga-trace [--size 320x240]
        [--rounds 3] [--scenes area,lens] [--out DIR]

Error: RMSE over all pixels and channels, in 8-bit levels of the PNG, of each render against
its OWN renderer's reference, so that the two renderers' differences in shading do not count:
- ours: cga-trace at --spp 1024 (stratified) at the same size;
- POV-Ray's: the scene with no anti-aliasing at K times the width and height (a K x K grid of
  rays in each pixel; K = 32, 1,024 rays, except lens: 16, whose every ray already carries 16
  focal-blur rays, 4,096 in all), box-filtered down in linear light (sRGB decoded, averaged,
  encoded), as both renderers average a pixel's samples in linear light.
References are cached in --out by scene, size and K, and rendered again when the scene file (or,
for ours, the binary) is newer.
"""
import argparse
import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile

import vase_mesh

try:
    import numpy as np
    from PIL import Image
except ImportError:
    sys.exit("needs numpy and pillow: python3 -m venv /tmp/aa && /tmp/aa/bin/pip install numpy pillow, "
             "then run this with /tmp/aa/bin/python")

HERE = os.path.dirname(os.path.abspath(__file__))
SCENES = ["area", "glass", "glassarea", "lens", "mesh", "textures"]
REF_K = {"lens": 16}  # POV-Ray reference supersampling per axis; 32 elsewhere
REF_K_WHY = {"lens": "each ray takes 16 focal-blur rays, 4,096 a pixel (K = 32 costs 4 times as much)"}
REF_SPP = 1024
POV_AA = {  # POV-Ray's adaptive anti-aliasing as a user runs it
    "+A0.3 +AM2 +R3": ["+A0.3", "+AM2", "+R3"],
    "+A0.3 +AM1 +R3 +J": ["+A0.3", "+AM1", "+R3", "+J"],
}
SPPS = [4, 8, 16, 32, 64]
THRESHOLDS = [0.3, 0.2, 0.1, 0.05]
MINS = [1, 2, 4]  # --adaptive-min: the first samples every pixel takes
# (threshold, first samples or "corners"); (None, None): plain --spp. Corners cut a pixel
# log4(spp) times, so only spp 4, 16 and 64 are distinct.
# Corners also at coarser thresholds: the same T need not give POV-Ray's error, so which T
# matches it is measured, not assumed.
CORNER_THRESHOLDS = [0.5, 0.4] + THRESHOLDS
SETTINGS = [(None, None)] + [(t, m) for t in THRESHOLDS for m in MINS] + [(t, "corners") for t in CORNER_THRESHOLDS]
CORNER_SPPS = [4, 16, 64]
# Scenes with a lens also sweep corners whose every point is the mean of B lens rays
# (--blur-samples B, POV-Ray's blur_samples): (threshold, "corners+bB").
BLUR = {"lens": [8, 16]}

Image.MAX_IMAGE_PIXELS = None  # the POV-Ray reference is K^2 times the picture


def cpu_run(cmd):
    """Runs cmd (output to a log, shown if it fails); returns its CPU time, user + sys."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    with tempfile.TemporaryFile() as log:
        rc = subprocess.run(cmd, stdout=log, stderr=log).returncode
        if rc != 0:
            log.seek(0)
            sys.exit(f"failed ({rc}): {' '.join(cmd)}\n{log.read().decode(errors='replace')[-3000:]}")
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


# POV-Ray's library paths: this folder (textures.pov finds its image map relative to it), and
# where mesh_include wrote mesh.pov's mesh.
LIBS = [HERE]


def pov_cmd(scene, out, w, h, flags):
    return ["povray", f"+I{HERE}/{scene}.pov", *(f"+L{d}" for d in LIBS), f"+O{out}", f"+W{w}",
            f"+H{h}", "-D", "+WT1", *flags]


def mesh_include(folder):
    """Writes folder/vase_mesh.inc, mesh.pov's `Vase` (vase_mesh.py), and adds folder to
    POV-Ray's library paths."""
    vase_mesh.write(folder)
    if folder not in LIBS:
        LIBS.append(folder)


def ours_cmd(binary, scene, out, w, h, spp, setting):
    cmd = [binary, "render", f"{HERE}/{scene}.toml", "-o", out, "--width", str(w),
           "--height", str(h), "--threads", "1", "--spp", str(spp)]
    return cmd + adaptive_flags(setting)


def adaptive_flags(setting):
    """Our adaptive flags for (threshold, first samples or "corners")."""
    t, m = setting
    if t is None:
        return []
    if m == "corners":
        return ["--adaptive", str(t), "--adaptive-method", "corners"]
    if str(m).startswith("corners+b"):
        return ["--adaptive", str(t), "--adaptive-method", "corners", "--blur-samples", m[len("corners+b"):]]
    return ["--adaptive", str(t), "--adaptive-min", str(m)]


def runs(spp, setting):
    """Whether the sweep renders this setting at this spp (corners only where log4 differs)."""
    return not str(setting[1]).startswith("corners") or spp in CORNER_SPPS


def load(path):
    return np.asarray(Image.open(path).convert("RGB"), dtype=np.float64)


def rmse(path, ref):
    return float(np.sqrt(np.mean((load(path) - ref) ** 2)))


def srgb_decode(v):
    return np.where(v <= 0.04045, v / 12.92, ((v + 0.055) / 1.055) ** 2.4)


def srgb_encode(v):
    return np.where(v <= 0.0031308, v * 12.92, 1.055 * np.power(v, 1 / 2.4) - 0.055)


def box_down(big, w, h, k):
    """Averages each k x k block of the 8-bit sRGB image big in linear light. (Each ray's value
    was clamped to 1 first, whereas an anti-aliased pixel clamps the average: they differ only
    at the rims of highlights brighter than 1, under 1.2% of the pixels in these scenes.)"""
    img = np.asarray(Image.open(big).convert("RGB"))
    assert img.shape == (h * k, w * k, 3), img.shape
    lut = srgb_decode(np.arange(256) / 255.0)
    out = np.empty((h, w, 3), dtype=np.uint8)
    for y in range(h):  # a row at a time keeps the float copy small
        lin = lut[img[y * k:(y + 1) * k]].reshape(k, w, k, 3).mean(axis=(0, 2))
        out[y] = np.clip(np.round(srgb_encode(lin) * 255), 0, 255).astype(np.uint8)
    return out


def fresh(path, *sources):
    """A cached reference is used unless what made it (scene file, binary) has changed since."""
    return os.path.exists(path) and all(os.path.getmtime(path) > os.path.getmtime(s) for s in sources)


def references(binary, scene, w, h, out, k):
    """Returns (POV-Ray reference, ours) as float arrays, rendering what is not cached."""
    pov_ref = f"{out}/ref-{scene}-{w}x{h}-pov-k{k}.png"
    our_ref = f"{out}/ref-{scene}-{w}x{h}-ours-spp{REF_SPP}.png"
    note = "cached"
    if not fresh(pov_ref, f"{HERE}/{scene}.pov"):
        big = f"{out}/big-{scene}.png"
        t = cpu_run(pov_cmd(scene, big, w * k, h * k, ["-A"]))
        Image.fromarray(box_down(big, w, h, k)).save(pov_ref)
        os.remove(big)
        note = f"{t:.1f} s CPU"
    why = "" if k == 32 else f"; K = {k}, not 32: {REF_K_WHY.get(scene, 'set by --ref-k')}"
    print(f"  {scene:10} POV-Ray: {w * k}x{h * k} -A, {k}x{k} boxes in linear light ({note}{why})")
    note = "cached"
    if not fresh(our_ref, f"{HERE}/{scene}.toml", binary):
        note = f"{cpu_run(ours_cmd(binary, scene, our_ref, w, h, REF_SPP, (None, None))):.1f} s CPU"
    print(f"  {scene:10} ours: --spp {REF_SPP} ({note})")
    return load(pov_ref), load(our_ref)


def machine():
    model = "?"
    with open("/proc/cpuinfo") as f:
        for line in f:
            if line.startswith("model name"):
                model = line.split(":", 1)[1].strip()
                break
    return f"{model}, {os.cpu_count()} logical cores"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("binary", help="the cga-trace binary")
    ap.add_argument("--size", default="320x240", help="WxH (default 320x240)")
    ap.add_argument("--rounds", type=int, default=3, help="timed rounds (default 3)")
    ap.add_argument("--scenes", default=",".join(SCENES), help="comma-separated (default all)")
    ap.add_argument("--out", help="keep the images and references here (default a temp dir, removed)")
    ap.add_argument("--ref-k", type=int, help="POV-Ray reference supersampling per axis for every "
                    "scene (default 32, lens 16)")
    args = ap.parse_args()
    binary = os.path.realpath(args.binary)
    w, h = map(int, args.size.lower().split("x"))
    scenes = args.scenes.split(",")
    out = args.out or tempfile.mkdtemp(prefix="adaptive-")
    os.makedirs(out, exist_ok=True)
    mesh_include(out)

    help_text = subprocess.run([binary, "render", "--help"], capture_output=True, text=True).stdout
    settings = SETTINGS if "--adaptive-min" in help_text else [(None, None)]
    if len(settings) == 1:
        print("warning: this cga-trace has no --adaptive-min: sweeping plain --spp only")
    elif "--adaptive-method" not in help_text:
        print("warning: this cga-trace has no --adaptive-method: sweeping adaptive samples only")
        settings = [s for s in settings if s[1] != "corners"]
    blur = "--blur-samples" in help_text

    print(f"machine: {machine()}; one thread each, CPU time = user + sys of the child, "
          f"median of {args.rounds} interleaved rounds; {w}x{h}; images in {out}"
          + ("" if args.out else " (removed at the end)"))
    print("POV-Ray: " + " ".join(pov_cmd("SCENE", "OUT.png", w, h, ["FLAGS"])).replace(HERE, "$HERE"))
    print("ours:    " + " ".join(ours_cmd(binary, "SCENE", "OUT.png", w, h, "N", (None, None))).replace(HERE, "$HERE")
          + " [--adaptive T --adaptive-min M | --adaptive T --adaptive-method corners [--blur-samples B]]")
    print(f"error: RMSE in 8-bit levels against the renderer's own reference ($HERE = {HERE})")
    print("references:")

    summary, sweeps = [], {}
    for scene in scenes:
        k = args.ref_k or REF_K.get(scene, 32)
        pov_ref, our_ref = references(binary, scene, w, h, out, k)
        # jobs: key -> (command, its picture, its renderer's reference); each round runs POV-Ray's
        # settings and then ours, so that a slow spell of the machine falls on both
        jobs = {}
        scene_settings = settings + [(t, f"corners+b{b}") for b in (BLUR.get(scene, []) if blur else [])
                                     for t in THRESHOLDS]
        for name, pov_flags in POV_AA.items():
            png = f"{out}/{scene}-pov{''.join(pov_flags).replace('+', '_')}.png"
            jobs[("pov", name)] = (pov_cmd(scene, png, w, h, pov_flags), png, pov_ref)
        for spp in SPPS:
            for setting in filter(lambda st: runs(spp, st), scene_settings):
                png = f"{out}/{scene}-ours-spp{spp}-t{setting[0]}-m{setting[1]}.png"
                jobs[("ours", spp, setting)] = (ours_cmd(binary, scene, png, w, h, spp, setting), png, our_ref)
        times = {key: [] for key in jobs}
        for _ in range(args.rounds):
            for key, (cmd, _, _) in jobs.items():
                times[key].append(cpu_run(cmd))
        res = {key: (rmse(png, ref), statistics.median(times[key])) for key, (_, png, ref) in jobs.items()}
        sweeps[scene] = res
        for name in POV_AA:
            perr, ptime = res[("pov", name)]
            ok = [(t, key) for key, (e, t) in res.items() if key[0] == "ours" and e <= perr]
            if ok:
                otime, key = min(ok, key=lambda tk: tk[0])
                setting = " ".join([f"--spp {key[1]}", *adaptive_flags(key[2])]).replace("--adaptive-min", "-min")
                setting = setting.replace("--adaptive-method corners", "corners").replace("--blur-samples", "blur")
                summary.append((scene, name, perr, ptime, setting, res[key][0], otime, ptime / otime))
            else:
                summary.append((scene, name, perr, ptime, "none reaches it", float("nan"), float("nan"), float("nan")))

    print("\nequal error: our fastest setting whose error <= POV-Ray's (goal: POV/ours >= 2)")
    print(f"{'scene':10} {'POV-Ray':19} {'err':>6} {'CPU s':>7}   {'ours':36} {'err':>6} {'CPU s':>7} {'POV/ours':>9}")
    for s, name, pe, pt, setting, oe, ot, ratio in summary:
        print(f"{s:10} {name:19} {pe:6.2f} {pt:7.3f}   {setting:36} {oe:6.2f} {ot:7.3f} {ratio:9.2f}")

    print("\nour sweep: error (8-bit RMSE) / CPU s; columns: --adaptive threshold/--adaptive-min, or "
          "threshold/corners (none = plain --spp; - = not run)")
    for scene, res in sweeps.items():
        columns = list(dict.fromkeys(key[2] for key in res if key[0] == "ours"))
        print(f"{scene:10}" + "".join(f"{'none' if t is None else f'{t}/{m}':>15}" for t, m in columns))
        for spp in SPPS:
            cells = (f"{res[('ours', spp, st)][0]:7.2f}/{res[('ours', spp, st)][1]:<7.3f}"
                     if ('ours', spp, st) in res else f"{'-':>15}" for st in columns)
            print(f"  spp {spp:<4}" + "".join(cells))
    if not args.out:
        shutil.rmtree(out)


if __name__ == "__main__":
    main()
