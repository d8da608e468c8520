#!/usr/bin/env python3
"""Writes sky.pfm (run from this folder): a procedural HDR sky, 256 x 128 pixels, equirectangular
in chapter 03's convention (the left and right edges look along -z, the centre column along +z, the top row straight up;
u = phi / 2 pi with phi = atan2(x, -z), v = theta / pi from +y):

  - the upper half, a sky: deep blue at the zenith, pale near the horizon;
  - the lower half, a dark brown ground, a little brighter towards the horizon;
  - a sun: a disc of angular radius 2 degrees (about three pixels across), of radiance 1000,
    35 degrees above the horizon, to the left of the camera of scene-environment.json and a little behind it,
    so that it lights the spheres from the front left and throws their shadows to the right onto the floor.

The sun gives about four fifths of the light reaching the floor: a small, very bright source
that BSDF sampling rarely finds and light sampling finds every time. PFM stores 32-bit floats
uncompressed, rows from the bottom of the image up (384 KB)."""
import math
import struct

WIDTH, HEIGHT = 256, 128
SUPERSAMPLES = 4  # per pixel and axis, for the sun's edge
SUN_ELEVATION_DEGREES = 35.0
SUN_RADIUS_DEGREES = 2.0
SUN_RADIANCE = (1000.0, 950.0, 850.0)
ZENITH = (0.10, 0.25, 0.75)
HORIZON = (0.75, 0.85, 1.00)
GROUND = (0.06, 0.045, 0.03)
GROUND_HORIZON = (0.18, 0.15, 0.12)


def direction(u, v):
    phi, theta = 2 * math.pi * u, math.pi * v
    return (math.sin(theta) * math.sin(phi), math.cos(theta), -math.sin(theta) * math.cos(phi))


def mix(a, b, t):
    return tuple(x + (y - x) * t for x, y in zip(a, b))


def normalise(v):
    length = math.sqrt(sum(c * c for c in v))
    return tuple(c / length for c in v)


elevation = math.radians(SUN_ELEVATION_DEGREES)
# Towards the sun: to the left of the camera (which looks along +z; +x is on the image's left), a
# little behind it.
SUN_DIRECTION = normalise((0.85 * math.cos(elevation), math.sin(elevation), -0.5 * math.cos(elevation)))
COS_SUN = math.cos(math.radians(SUN_RADIUS_DEGREES))


def sky(d):
    if d[1] >= 0:
        return mix(HORIZON, ZENITH, math.sqrt(d[1]))
    return mix(GROUND_HORIZON, GROUND, math.sqrt(-d[1]))


def pixel(x, y):
    # The sky at the pixel's centre, plus the sun's share of the pixel's area.
    base = sky(direction((x + 0.5) / WIDTH, (y + 0.5) / HEIGHT))
    covered = 0
    for i in range(SUPERSAMPLES):
        for j in range(SUPERSAMPLES):
            d = direction((x + (i + 0.5) / SUPERSAMPLES) / WIDTH, (y + (j + 0.5) / SUPERSAMPLES) / HEIGHT)
            covered += sum(a * b for a, b in zip(d, SUN_DIRECTION)) >= COS_SUN
    share = covered / SUPERSAMPLES ** 2
    return tuple(b * (1 - share) + s * share for b, s in zip(base, SUN_RADIANCE))


def main():
    rows = [[pixel(x, y) for x in range(WIDTH)] for y in range(HEIGHT)]
    with open("sky.pfm", "wb") as out:
        out.write(b"PF\n%d %d\n-1.0\n" % (WIDTH, HEIGHT))
        for row in reversed(rows):  # PFM: bottom row first
            out.write(b"".join(struct.pack("<3f", *p) for p in row))


if __name__ == "__main__":
    main()
