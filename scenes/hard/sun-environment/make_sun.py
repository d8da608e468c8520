#!/usr/bin/env python3
"""Writes sun.pfm (run from this folder): a 64 x 32 equirectangular environment that is hard to
sample. Its top 4 rows (around the zenith) and its whole lower half are black; rows 4 to 15 are a
dim blue sky of radiance (0.3, 0.4, 0.5); one pixel, column 40 of row 9 (about 39 degrees above the
horizon), is a sun of radiance 1e6 in every channel that gives about 99.9 % of the light reaching
a floor. PFM: 32-bit floats, little endian, rows from the bottom of the image up."""
import struct

WIDTH, HEIGHT = 64, 32
SKY = (0.3, 0.4, 0.5)
SUN = (1e6, 1e6, 1e6)
SUN_PIXEL = (40, 9)  # column, row from the top


def radiance(x, y):
    if (x, y) == SUN_PIXEL:
        return SUN
    if 4 <= y < HEIGHT // 2:
        return SKY
    return (0.0, 0.0, 0.0)


with open("sun.pfm", "wb") as out:
    out.write(b"PF\n%d %d\n-1.0\n" % (WIDTH, HEIGHT))
    for y in reversed(range(HEIGHT)):
        out.write(b"".join(struct.pack("<3f", *radiance(x, y)) for x in range(WIDTH)))
