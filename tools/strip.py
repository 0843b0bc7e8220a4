#!/usr/bin/env python3
"""Render an animation's frames with cga-trace and paste them side by side into one strip.

Provenance: docs/images/animation-strip.png, the README gallery's animation strip, is drawn by

    cargo build --release -p cga-trace
    python3 tools/strip.py target/release/cga-trace cga-trace/scenes/animation.toml 6

which runs `cga-trace render SCENE -o TMP/frame.png --frames N` (the frames come out as
TMP/frame_0000.png … TMP/frame_{N-1}.png, at the times 0, 1/(N−1), …, 1 of the scene's
`motion` keys), shrinks each frame to --frame-size (Lanczos) and pastes them left to right,
--gap pixels apart on a --gap-colour ground, into the output (default
docs/images/animation-strip.png, relative to the repository root).

Usage:
    python3 tools/strip.py BINARY SCENE N [-o OUT] [--frame-size 200x150] [--gap 4]
                           [--gap-colour #101218] [--render-size 320x240] [--keep DIR]
                           [-- EXTRA cga-trace ARGS…]

Needs python3 and Pillow (`pip install pillow`). The frames are rendered at --render-size
(passed as --width/--height) into a temporary directory, removed afterwards unless --keep
names a directory to render into instead.
"""

import argparse
import os
import subprocess
import sys
import tempfile
import time

from PIL import Image

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def size(text):
    """`WxH` as a pair of positive integers."""
    try:
        w, h = (int(v) for v in text.lower().split("x"))
    except ValueError:
        raise argparse.ArgumentTypeError(f"`{text}` is not WIDTHxHEIGHT")
    if w <= 0 or h <= 0:
        raise argparse.ArgumentTypeError(f"`{text}`: sizes must be > 0")
    return w, h


def colour(text):
    """`#rrggbb` as an RGB triple."""
    t = text.lstrip("#")
    if len(t) != 6:
        raise argparse.ArgumentTypeError(f"`{text}` is not #rrggbb")
    return tuple(int(t[i : i + 2], 16) for i in (0, 2, 4))


def main():
    argv = sys.argv[1:]
    extra = []
    if "--" in argv:
        cut = argv.index("--")
        argv, extra = argv[:cut], argv[cut + 1 :]
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("binary", help="the cga-trace binary")
    p.add_argument("scene", help="the scene file (with `motion` keys)")
    p.add_argument("frames", type=int, help="how many frames (N ≥ 2)")
    p.add_argument("-o", "--output", default=os.path.join(ROOT, "docs/images/animation-strip.png"))
    p.add_argument("--frame-size", type=size, default=(200, 150), help="each frame in the strip")
    p.add_argument("--render-size", type=size, default=(320, 240), help="each frame rendered")
    p.add_argument("--gap", type=int, default=4, help="pixels between frames (and around them)")
    p.add_argument("--gap-colour", type=colour, default=colour("#101218"))
    p.add_argument("--keep", help="render the frames into this directory and keep them")
    a = p.parse_args(argv)
    if a.frames < 2:
        p.error("N must be at least 2")
    if a.gap < 0:
        p.error("--gap must be ≥ 0")

    with tempfile.TemporaryDirectory() as tmp:
        out_dir = a.keep or tmp
        os.makedirs(out_dir, exist_ok=True)
        target = os.path.join(out_dir, "frame.png")
        w, h = a.render_size
        cmd = [a.binary, "render", a.scene, "-o", target, "--frames", str(a.frames),
               "--width", str(w), "--height", str(h), *extra]
        print("+", " ".join(cmd), file=sys.stderr)
        start = time.monotonic()
        run = subprocess.run(cmd)
        if run.returncode != 0:
            sys.exit(f"strip.py: cga-trace failed (exit status {run.returncode})")
        took = time.monotonic() - start
        print(f"{a.frames} frames in {took:.2f} s ({took / a.frames:.2f} s a frame)", file=sys.stderr)

        fw, fh = a.frame_size
        g = a.gap
        strip = Image.new("RGB", (a.frames * fw + (a.frames + 1) * g, fh + 2 * g), a.gap_colour)
        for i in range(a.frames):
            path = os.path.join(out_dir, f"frame_{i:04}.png")
            with Image.open(path) as im:
                frame = im.convert("RGB").resize((fw, fh), Image.Resampling.LANCZOS)
            strip.paste(frame, (g + i * (fw + g), g))
        os.makedirs(os.path.dirname(os.path.abspath(a.output)), exist_ok=True)
        strip.save(a.output, optimize=True)
        print(f"-> {a.output} ({strip.width}×{strip.height})", file=sys.stderr)


if __name__ == "__main__":
    main()
