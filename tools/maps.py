#!/usr/bin/env python3
"""The texture and environment maps the shipped scenes read (cga-trace/scenes/maps/), drawn
here so that their provenance is this script: `python3 tools/maps.py` (needs Pillow).

- grid.png: 256 × 128, a test grid for (u, v) ∈ [0, 1)²: hue across u, lightness down v,
  dark lines every 1/16 of u and 1/8 of v, and a white mark in the cell at u, v < 1/16, 1/8.
- sky.png: 512 × 256 equirectangular sky (longitude across, colatitude down): a blue
  gradient above the horizon, a warm sun disk (5° across) at longitude 30°, elevation 35°,
  and a grey-brown ground below.
"""
import colorsys
import math
import pathlib

from PIL import Image

out = pathlib.Path(__file__).resolve().parent.parent / "cga-trace" / "scenes" / "maps"
out.mkdir(parents=True, exist_ok=True)

w, h = 256, 128
grid = Image.new("RGB", (w, h))
for y in range(h):
    for x in range(w):
        u, v = (x + 0.5) / w, (y + 0.5) / h
        r, g, b = colorsys.hls_to_rgb(u, 0.35 + 0.35 * v, 0.75)
        if x % 16 == 0 or y % 16 == 0:
            r, g, b = 0.08, 0.08, 0.1
        if x < 16 and y < 16 and 4 <= x < 12 and 4 <= y < 12:
            r, g, b = 1.0, 1.0, 1.0
        grid.putpixel((x, y), tuple(int(round(255 * c)) for c in (r, g, b)))
grid.save(out / "grid.png")

w, h = 512, 256
sun_lon, sun_lat = math.radians(30.0), math.radians(35.0)
sun = (math.cos(sun_lat) * math.cos(sun_lon), math.cos(sun_lat) * math.sin(sun_lon), math.sin(sun_lat))
sky = Image.new("RGB", (w, h))
for y in range(h):
    for x in range(w):
        lon = (x + 0.5) / w * 2 * math.pi - math.pi
        theta = (y + 0.5) / h * math.pi
        d = (math.sin(theta) * math.cos(lon), math.sin(theta) * math.sin(lon), math.cos(theta))
        s = d[2]
        if s >= 0:
            c = tuple(a * (1 - s) + b * s for a, b in zip((0.85, 0.88, 0.95), (0.25, 0.45, 0.85)))
        else:
            c = tuple(a * (1 + s) + b * (-s) for a, b in zip((0.5, 0.45, 0.4), (0.25, 0.22, 0.2)))
        if sum(a * b for a, b in zip(d, sun)) > math.cos(math.radians(2.5)):
            c = (1.0, 0.95, 0.8)
        sky.putpixel((x, y), tuple(int(round(255 * v)) for v in c))
sky.save(out / "sky.png")
