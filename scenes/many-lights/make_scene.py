#!/usr/bin/env python3
"""Writes hall.obj, lamps.obj and many-lights.mtl (run from this folder): a wide, low hall lit by
1,536 small square lamps of very different powers, the scene of chapter 10 (many lights).

  - the hall: x in [-20, 20], y in [0, 3], z in [0, 60] metres, closed (floor, ceiling, four
    walls), with two rows of square columns (0.6 x 0.6, floor to ceiling) at x = -10 and 10 and
    a few crates on the floor, all diffuse;
  - the lamps: a grid of 32 x 48 squares, 0.25 x 0.25, 1.25 apart (the columns stand between
    them), hanging at y = 2.4 and emitting downward only (their backs are black). The irradiance
    a lamp at horizontal distance d gives the floor falls as h^2 / (h^2 + d^2)^2 (h = 2.4): about
    half a floor point's direct light comes from the dozen lamps within h of it and four fifths
    from the fifty within 2h, out of 1,536;
  - the lamps' radiances: eight classes spaced evenly in log over two orders of magnitude
    (lamp_0 to lamp_7, 0.6 to 60), chosen per lamp from a smooth pattern of brighter and dimmer
    regions plus a pseudo-random jitter (splitmix64, fixed seed), and six brighter lamps
    (lamp_bright, ten times the brightest class).

Objects are written as separate `o` groups: each is a mesh of its own, so the brute-force
accelerator tests a lamp's triangles only for rays that meet its block's bounding box (8 x 8
lamps per block)."""
import math
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ in scenes/tools
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tools"))
from meshes import ObjBuilder  # noqa: E402

MTL = "many-lights.mtl"
LAMPS_X, LAMPS_Z, PITCH = 32, 48, 1.25   # the grid: lamp (i, j) is centred at x = -20 + 1.25 (i + 1/2), z = 1.25 (j + 1/2)
HALF_WIDTH, HEIGHT, LENGTH = LAMPS_X * PITCH / 2, 3.0, LAMPS_Z * PITCH
LAMP_SIDE, LAMP_Y = 0.25, 2.4
BLOCK = 8                                # lamps per side of one `o` group
CLASSES = 8
DIMMEST, RANGE = 0.6, 100.0              # class k has radiance DIMMEST * RANGE^(k / (CLASSES - 1))
BRIGHT = 10.0 * DIMMEST * RANGE          # lamp_bright
BRIGHT_LAMPS = [(3, 4), (26, 9), (12, 17), (20, 25), (6, 33), (23, 42)]  # (i, j)
SEED = 10
COLUMN_XS, COLUMN_ZS, COLUMN_SIDE = (-10.0, 10.0), (7.5, 17.5, 27.5, 37.5, 47.5), 0.6  # between lamps
# Crates: centre x, z, sides (x, y, z), rotation about y in degrees, bottom y, material.
CRATES = [
    (3.0, 9.0, (1.2, 1.0, 1.2), 20.0, 0.0, "crate_wood"),
    (3.0, 9.0, (0.7, 0.6, 0.7), 35.0, 1.0, "crate_red"),
    (-4.5, 12.5, (2.0, 0.8, 1.0), -10.0, 0.0, "crate_blue"),
    (-2.0, 20.0, (1.0, 1.5, 1.0), 45.0, 0.0, "crate_grey"),
    (5.5, 24.0, (1.6, 1.2, 1.6), 0.0, 0.0, "crate_wood"),
    (12.5, 15.0, (1.2, 0.9, 2.4), 15.0, 0.0, "crate_red"),
    (-12.5, 30.0, (1.4, 1.4, 1.4), 30.0, 0.0, "crate_grey"),
    (1.0, 33.0, (3.0, 0.7, 1.2), 5.0, 0.0, "crate_blue"),
    (-7.0, 42.0, (1.6, 1.0, 1.6), -25.0, 0.0, "crate_wood"),
    (8.0, 45.0, (1.0, 1.8, 1.0), 10.0, 0.0, "crate_red"),
]
MATERIALS = [
    ("floor", (0.4, 0.4, 0.4)),
    ("wall", (0.6, 0.58, 0.55)),
    ("ceiling", (0.7, 0.7, 0.7)),
    ("column", (0.55, 0.55, 0.55)),
    ("crate_wood", (0.55, 0.4, 0.25)),
    ("crate_red", (0.6, 0.15, 0.1)),
    ("crate_blue", (0.15, 0.25, 0.55)),
    ("crate_grey", (0.3, 0.3, 0.3)),
]


class SplitMix64:
    """Steele, Lea and Flood's splitmix64: the same numbers on every Python."""

    def __init__(self, seed):
        self.state = seed & 0xFFFFFFFFFFFFFFFF

    def uniform(self):
        self.state = (self.state + 0x9E3779B97F4A7C15) & 0xFFFFFFFFFFFFFFFF
        z = self.state
        z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & 0xFFFFFFFFFFFFFFFF
        z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & 0xFFFFFFFFFFFFFFFF
        return ((z ^ (z >> 31)) >> 11) / float(1 << 53)  # in [0, 1)


class ObjectsObj(ObjBuilder):
    """An ObjBuilder whose objects become `o` groups (one mesh each in the loader)."""

    def __init__(self, mtllib, decimals=4):
        super().__init__(mtllib, decimals)
        self.objects = []  # (name, first group)

    def begin(self, name):
        self.objects.append((name, len(self.groups)))

    def write(self, path, header):
        vertex = "v %%.%df %%.%df %%.%df\n" % ((self.decimals,) * 3)
        starts = dict((first, name) for name, first in self.objects)
        with open(path, "w") as out:
            out.write(header)
            out.write("mtllib %s\n" % self.mtllib)
            for v in self.vertices:
                out.write(vertex % tuple(v))
            for g, (material, faces) in enumerate(self.groups):
                if g in starts:
                    out.write("o %s\n" % starts[g])
                out.write("usemtl %s\n" % material)
                for f in faces:
                    out.write("f " + " ".join(str(i + 1) for i in f) + "\n")


def quad_faces():
    return [(0, 1, 2), (0, 2, 3)]


def lamp(cx, cz):
    """A square at y = LAMP_Y, counter-clockwise seen from below: it emits downward."""
    h = LAMP_SIDE / 2
    return [(cx - h, LAMP_Y, cz - h), (cx + h, LAMP_Y, cz - h), (cx + h, LAMP_Y, cz + h), (cx - h, LAMP_Y, cz + h)]


def box(cx, cz, sides, degrees, bottom):
    """A box standing at y = bottom, rotated about its vertical axis, without its bottom face;
    wound counter-clockwise seen from outside."""
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    hx, hz = sides[0] / 2, sides[2] / 2
    ring = [(-hx, -hz), (-hx, hz), (hx, hz), (hx, -hz)]  # clockwise seen from above
    ring = [(cx + c * x + s * z, cz - s * x + c * z) for x, z in ring]
    top = bottom + sides[1]
    vertices = [(x, bottom, z) for x, z in ring] + [(x, top, z) for x, z in ring]
    faces = [(4, 5, 6), (4, 6, 7)]  # top, facing up
    for k in range(4):
        n = (k + 1) % 4
        faces += [(k, n, 4 + n), (k, 4 + n, 4 + k)]
    return vertices, faces


def radiance_class(i, j, rng):
    """A lamp's class, 0 (dimmest) to CLASSES - 1: a smooth pattern of brighter and dimmer
    stretches of the hall, jittered per lamp."""
    x, z = -HALF_WIDTH + (i + 0.5) * PITCH, (j + 0.5) * PITCH
    smooth = 0.5 + 0.3 * math.sin(2 * math.pi * z / 25.0 + 1.0) * math.cos(2 * math.pi * x / 32.0) \
        + 0.12 * math.sin(2 * math.pi * (x + z) / 14.0)
    u = smooth + 0.3 * (rng.uniform() - 0.5)
    return min(CLASSES - 1, max(0, int(u * CLASSES)))


def class_radiance(k):
    return DIMMEST * RANGE ** (k / (CLASSES - 1))


def main():
    rng = SplitMix64(SEED)
    area = LAMP_SIDE * LAMP_SIDE
    # The lamps, in blocks of BLOCK x BLOCK (one `o` group each), rows of increasing z.
    lamps = ObjectsObj(MTL, 4)
    classes = {}
    for j in range(LAMPS_Z):
        for i in range(LAMPS_X):
            classes[(i, j)] = radiance_class(i, j, rng)
    counts = [0] * CLASSES
    for bj in range(0, LAMPS_Z, BLOCK):
        for bi in range(0, LAMPS_X, BLOCK):
            lamps.begin("lamps_%d_%d" % (bi // BLOCK, bj // BLOCK))
            for j in range(bj, bj + BLOCK):
                for i in range(bi, bi + BLOCK):
                    name = "lamp_bright" if (i, j) in BRIGHT_LAMPS else "lamp_%d" % classes[(i, j)]
                    if (i, j) not in BRIGHT_LAMPS:
                        counts[classes[(i, j)]] += 1
                    lamps.add(name, lamp(-HALF_WIDTH + (i + 0.5) * PITCH, (j + 0.5) * PITCH), quad_faces())
    lamps.write("lamps.obj", "# many-lights: %d x %d lamps of %g x %g at y = %g emitting downward, in %d blocks of %d x %d. "
                "Generated by make_scene.py.\n" % (LAMPS_X, LAMPS_Z, LAMP_SIDE, LAMP_SIDE, LAMP_Y,
                                                   (LAMPS_X // BLOCK) * (LAMPS_Z // BLOCK), BLOCK, BLOCK))
    # The hall, its columns and the crates.
    hall = ObjectsObj(MTL, 4)
    w, h, l = HALF_WIDTH, HEIGHT, LENGTH
    hall.begin("room")
    hall.add("floor", [(-w, 0, 0), (-w, 0, l), (w, 0, l), (w, 0, 0)], quad_faces())       # facing up
    hall.add("ceiling", [(-w, h, 0), (w, h, 0), (w, h, l), (-w, h, l)], quad_faces())     # facing down
    hall.add("wall", [(-w, 0, 0), (w, 0, 0), (w, h, 0), (-w, h, 0)]                       # z = 0, facing +z
             + [(w, 0, l), (-w, 0, l), (-w, h, l), (w, h, l)]                             # z = l, facing -z
             + [(-w, 0, l), (-w, 0, 0), (-w, h, 0), (-w, h, l)]                           # x = -w, facing +x
             + [(w, 0, 0), (w, 0, l), (w, h, l), (w, h, 0)],                              # x = w, facing -x
             [(4 * k + a, 4 * k + b, 4 * k + c) for k in range(4) for a, b, c in quad_faces()])
    for x in COLUMN_XS:
        for z in COLUMN_ZS:
            hall.begin("column_%+g_%g" % (x, z))
            vertices, faces = box(x, z, (COLUMN_SIDE, HEIGHT, COLUMN_SIDE), 0.0, 0.0)
            hall.add("column", vertices, faces[2:])  # no top: it touches the ceiling
    for n, (x, z, sides, degrees, bottom, material) in enumerate(CRATES):
        hall.begin("crate_%d" % (n + 1))
        hall.add(material, *box(x, z, sides, degrees, bottom))
    hall.write("hall.obj", "# many-lights: the hall (%g x %g x %g), its %d columns and %d crates. Generated by make_scene.py.\n"
               % (2 * HALF_WIDTH, HEIGHT, LENGTH, len(COLUMN_XS) * len(COLUMN_ZS), len(CRATES)))
    # Materials: the lamps' radiances and powers (pi A L, one-sided), then the diffuse surfaces.
    mtl = ["# many-lights: materials. Lamps of area %g emit downward; power pi A L.\n" % area]
    for k in range(CLASSES):
        L = class_radiance(k)
        mtl.append("# class %d: %d lamps, power %.6g each\nnewmtl lamp_%d\nKd 0 0 0\nKe %.6g %.6g %.6g\n"
                   % (k, counts[k], math.pi * area * L, k, L, L, L))
    mtl.append("# %d bright lamps, power %.6g each\nnewmtl lamp_bright\nKd 0 0 0\nKe %.6g %.6g %.6g\n"
               % (len(BRIGHT_LAMPS), math.pi * area * BRIGHT, BRIGHT, BRIGHT, BRIGHT))
    for name, albedo in MATERIALS:
        mtl.append("newmtl %s\nKd %g %g %g\n" % ((name,) + albedo))
    with open(MTL, "w") as out:
        out.write("\n".join(mtl))


if __name__ == "__main__":
    main()
