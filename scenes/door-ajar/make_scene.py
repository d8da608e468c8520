#!/usr/bin/env python3
"""Writes door-ajar.obj and door-ajar.mtl (run from this folder): two rooms in one closed box,
x in [0, 4], y in [0, 2.5], z in [0, 7] metres, divided at z = 4 by a wall 0.1 thick with a
doorway (x in [1.5, 2.4], y in [0, 2]). The camera's room (z < 4) has no light; the other room
(z > 4.1) has a bright ceiling light. The door, 0.9 x 2 x 0.04, hangs on the doorway's x = 1.5
side and is opened DOOR_DEGREES into the camera's room: light reaches the camera's room only
through the crack between the door's free edge and the frame, and after that by bouncing."""
import argparse
import math
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ in scenes/tools
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tools"))
from meshes import ObjBuilder  # noqa: E402

WIDTH, HEIGHT, DEPTH = 4.0, 2.5, 7.0
WALL_Z0, WALL_Z1 = 4.0, 4.1                 # the dividing wall
DOOR_X0, DOOR_X1, DOOR_TOP = 1.5, 2.4, 2.0  # the doorway
DOOR_THICKNESS = 0.04
DOOR_DEGREES = 12.0
LIGHT = (1.5, 2.5, 5.3, 6.3)                # x0, x1, z0, z1 of the ceiling light
LIGHT_Y = HEIGHT - 0.01
LIGHT_RADIANCE = (200.0, 186.0, 160.0)


def quad(a, b, c, d):
    """Two triangles a b c, a c d (counter-clockwise seen from the side the normal points to)."""
    return [a, b, c, d], [(0, 1, 2), (0, 2, 3)]


def box(corners):
    """A closed box from its 8 corners: bottom face p0..p3, top face p4..p7 above them."""
    faces = [(0, 2, 1), (0, 3, 2), (4, 5, 6), (4, 6, 7),
             (0, 1, 5), (0, 5, 4), (1, 2, 6), (1, 6, 5), (2, 3, 7), (2, 7, 6), (3, 0, 4), (3, 4, 7)]
    return list(corners), faces


def axis_box(x0, x1, y0, y1, z0, z1):
    return box([(x0, y0, z0), (x1, y0, z0), (x1, y0, z1), (x0, y0, z1),
                (x0, y1, z0), (x1, y1, z0), (x1, y1, z1), (x0, y1, z1)])


def main():
    global DOOR_DEGREES, LIGHT, LIGHT_RADIANCE
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--door-degrees", type=float, default=DOOR_DEGREES)
    parser.add_argument("--light-size", type=float, default=None,
                        help="side of a square light at the middle of the default one, its power kept")
    parser.add_argument("--name", default="door-ajar", help="writes NAME.obj and NAME.mtl")
    args = parser.parse_args()
    DOOR_DEGREES = args.door_degrees
    if args.light_size is not None:
        x0, x1, z0, z1 = LIGHT
        scale = (x1 - x0) * (z1 - z0) / (args.light_size * args.light_size)
        cx, cz, h = (x0 + x1) / 2, (z0 + z1) / 2, args.light_size / 2
        LIGHT = (cx - h, cx + h, cz - h, cz + h)
        LIGHT_RADIANCE = tuple(c * scale for c in LIGHT_RADIANCE)
    obj = ObjBuilder(os.path.basename(args.name) + ".mtl")
    # The outer box, seen from inside (diffuse surfaces are two-sided: winding only matters to emitters).
    obj.add("floor", *quad((0, 0, 0), (WIDTH, 0, 0), (WIDTH, 0, DEPTH), (0, 0, DEPTH)))
    obj.add("walls", *quad((0, HEIGHT, 0), (0, HEIGHT, DEPTH), (WIDTH, HEIGHT, DEPTH), (WIDTH, HEIGHT, 0)))
    obj.add("walls", *quad((0, 0, 0), (0, 0, DEPTH), (0, HEIGHT, DEPTH), (0, HEIGHT, 0)))
    obj.add("walls", *quad((WIDTH, 0, 0), (WIDTH, HEIGHT, 0), (WIDTH, HEIGHT, DEPTH), (WIDTH, 0, DEPTH)))
    obj.add("walls", *quad((0, 0, 0), (0, HEIGHT, 0), (WIDTH, HEIGHT, 0), (WIDTH, 0, 0)))
    obj.add("walls", *quad((0, 0, DEPTH), (WIDTH, 0, DEPTH), (WIDTH, HEIGHT, DEPTH), (0, HEIGHT, DEPTH)))
    # The dividing wall: three solid blocks around the doorway.
    obj.add("walls", *axis_box(0.0, DOOR_X0, 0.0, HEIGHT, WALL_Z0, WALL_Z1))
    obj.add("walls", *axis_box(DOOR_X1, WIDTH, 0.0, HEIGHT, WALL_Z0, WALL_Z1))
    obj.add("walls", *axis_box(DOOR_X0, DOOR_X1, DOOR_TOP, HEIGHT, WALL_Z0, WALL_Z1))
    # The door: hinged at (DOOR_X0, WALL_Z0), turned towards the camera's room (smaller z).
    angle = math.radians(DOOR_DEGREES)
    along = (math.cos(angle), -math.sin(angle))        # from the hinge to the free edge, in (x, z)
    across = (math.sin(angle), math.cos(angle))        # the door's thickness direction, in (x, z)
    length = DOOR_X1 - DOOR_X0 - 0.01                  # 1 cm of play at the frame when closed
    hinge = (DOOR_X0, WALL_Z0 - DOOR_THICKNESS)
    footprint = [hinge,
                 (hinge[0] + length * along[0], hinge[1] + length * along[1]),
                 (hinge[0] + length * along[0] + DOOR_THICKNESS * across[0],
                  hinge[1] + length * along[1] + DOOR_THICKNESS * across[1]),
                 (hinge[0] + DOOR_THICKNESS * across[0], hinge[1] + DOOR_THICKNESS * across[1])]
    obj.add("door", *box([(x, 0.001, z) for x, z in footprint] + [(x, DOOR_TOP - 0.005, z) for x, z in footprint]))
    # The light, facing down (its normal is -y: counter-clockwise seen from below).
    x0, x1, z0, z1 = LIGHT
    obj.add("light", *quad((x0, LIGHT_Y, z0), (x1, LIGHT_Y, z0), (x1, LIGHT_Y, z1), (x0, LIGHT_Y, z1)))
    # A sphere-free still life in the camera's room: a low box to catch the light from the crack.
    obj.add("table", *axis_box(2.6, 3.4, 0.0, 0.7, 2.4, 3.2))
    obj.write(args.name + ".obj", "# %s: two rooms, a door ajar between them (written by door-ajar/make_scene.py, "
              "door %g degrees)\n" % (os.path.basename(args.name), DOOR_DEGREES))
    with open(args.name + ".mtl", "w") as mtl:
        mtl.write("# %s materials (written by door-ajar/make_scene.py)\n" % os.path.basename(args.name))
        mtl.write("newmtl floor\nKd 0.55 0.5 0.45\n\n")
        mtl.write("newmtl walls\nKd 0.75 0.75 0.75\n\n")
        mtl.write("newmtl door\nKd 0.6 0.45 0.3\n\n")
        mtl.write("newmtl table\nKd 0.3 0.45 0.6\n\n")
        mtl.write("newmtl light\nKd 0 0 0\nKe %g %g %g\n" % LIGHT_RADIANCE)


if __name__ == "__main__":
    main()
