#!/usr/bin/env python3
"""Writes plates.obj, light-1.obj to light-4.obj, fill.obj, backdrop.obj and veach-mis.mtl (run
from this folder): the test scene of Veach and
Guibas 1995 (Veach's thesis 1997, figure 9.2) as remade for Mitsuba and pbrt-v4.

  - four glossy plates, 8 x 1 units, stepping down towards the camera; each is tilted so that
    its mirror direction from the camera's point of view points at the row of lights (its normal
    is the half vector between the camera and the lights' row as seen from its centre);
  - four spherical lights in a row at y = 0, z = 0, of radii 0.0333, 0.1, 0.3 and 0.9 and radiance
    1 / r^2, so that each emits the same power, 4 pi^2 r^2 L = 4 pi^2 (icospheres: 80 triangles for
    the two small ones, 320 for the two large);
  - a small square fill light up and to the side, facing the plates, and a dark floor and back wall.

The plates' materials (glossy, of four roughnesses) are given in scene.json by their MTL names
plate_1 (nearest the lights) to plate_4 (nearest the camera)."""
import math
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ in scenes/tools
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tools"))
from meshes import cross, icosphere, normalise, sub  # noqa: E402

CAMERA = (0.0, 2.0, 15.0)  # must match scene.json
# Plate centres (y, z) and depth; the plates span x in [-4, 4] (as in pbrt-v4's scene).
PLATES = [(-2.395, -0.135), (-3.063, 0.923), (-3.582, 2.223), (-3.908, 3.574)]
PLATE_DEPTH = 1.0
PLATE_HALF_WIDTH = 4.0
# (x, radius, subdivisions): radiance 1 / radius^2 makes every light's power 4 pi^2.
LIGHTS = [(-3.75, 1.0 / 30.0, 1), (-1.25, 0.1, 1), (1.25, 0.3, 2), (3.75, 0.9, 2)]
FILL = ((10.0, 10.0, 4.0), 1.0, 20.0)  # centre, side, radiance of a square facing the plates
FLOOR_Y = -4.5
WALL_Z = -3.0
EXTENT = 30.0


def add(a, b):
    return tuple(x + y for x, y in zip(a, b))


def scale(a, s):
    return tuple(x * s for x in a)


class Obj:
    def __init__(self):
        self.vertices, self.groups = [], []

    def add_face_group(self, material, vertices, faces):
        base = len(self.vertices)
        self.vertices += vertices
        self.groups.append((material, [tuple(base + i for i in f) for f in faces]))

    def write(self, path, header):
        with open(path, "w") as out:
            out.write(header)
            out.write("mtllib veach-mis.mtl\n")
            for v in self.vertices:
                out.write("v %.6f %.6f %.6f\n" % v)
            for material, faces in self.groups:
                out.write("usemtl %s\n" % material)
                for f in faces:
                    out.write("f " + " ".join(str(i + 1) for i in f) + "\n")


def plate(y, z):
    """The plate's four corners, counter-clockwise seen from the camera's side."""
    centre = (0.0, y, z)
    to_camera = normalise(sub(CAMERA, centre))
    to_lights = normalise(sub((0.0, 0.0, 0.0), centre))
    normal = normalise(add(to_camera, to_lights))
    along = normalise(cross(normal, (1.0, 0.0, 0.0)))  # in the plate, perpendicular to x
    h = PLATE_DEPTH / 2
    corners = [add(add(centre, scale((1.0, 0.0, 0.0), sx * PLATE_HALF_WIDTH)), scale(along, sz * h))
               for sx, sz in [(-1, -1), (1, -1), (1, 1), (-1, 1)]]
    a, b, c = corners[0], corners[1], corners[2]
    if sum(p * q for p, q in zip(cross(sub(b, a), sub(c, a)), normal)) < 0:
        corners.reverse()
    return corners


def square_facing(centre, side, target):
    """A square of the given side centred at `centre`, wound so that its front faces `target`."""
    normal = normalise(sub(target, centre))
    u = normalise(cross((0.0, 1.0, 0.0), normal))
    v = cross(normal, u)
    h = side / 2
    return [add(centre, add(scale(u, a * h), scale(v, b * h))) for a, b in [(-1, -1), (1, -1), (1, 1), (-1, 1)]]


def sphere(centre, radius, subdivisions):
    vertices, faces = icosphere(subdivisions)
    return [add(centre, scale(v, radius)) for v in vertices], faces


def mesh_area(vertices, faces):
    return sum(0.5 * math.sqrt(sum(c * c for c in cross(sub(vertices[b], vertices[a]), sub(vertices[c], vertices[a]))))
               for a, b, c in faces)


def main():
    # One OBJ per object: the accelerator skips a mesh whose bounding box a ray misses, so the
    # lights' hundreds of triangles cost only the rays that pass near them.
    plates = Obj()
    mtl = ["# veach-mis: materials. The plates' glossy materials are given in scene.json.\n"]
    for i, (y, z) in enumerate(PLATES):
        name = "plate_%d" % (i + 1)
        plates.add_face_group(name, plate(y, z), [(0, 1, 2), (0, 2, 3)])
        mtl.append("newmtl %s\nKd 0.5 0.5 0.5\n" % name)
    for i, (x, radius, subdivisions) in enumerate(LIGHTS):
        name = "light_%d" % (i + 1)
        vertices, faces = sphere((x, 0.0, 0.0), radius, subdivisions)
        light = Obj()
        light.add_face_group(name, vertices, faces)
        light.write("light-%d.obj" % (i + 1), "# veach-mis: light %d, an icosphere of radius %g (%d triangles). Generated by make_scene.py.\n"
                    % (i + 1, radius, len(faces)))
        # The icosphere's area is a little below the sphere's 4 pi r^2; the radiance makes up for
        # it, so every light's power pi A L is exactly 4 pi^2.
        radiance = 4 * math.pi / (mesh_area(vertices, faces))
        mtl.append("# radius %g, area %.6g: power pi A L = 4 pi^2\nnewmtl %s\nKd 0 0 0\nKe %.6g %.6g %.6g\n"
                   % (radius, mesh_area(vertices, faces), name, radiance, radiance, radiance))
    centre, side, radiance = FILL
    fill = Obj()
    fill.add_face_group("fill", square_facing(centre, side, (0.0, -3.0, 2.0)), [(0, 1, 2), (0, 2, 3)])
    fill.write("fill.obj", "# veach-mis: the fill light, a square facing the plates. Generated by make_scene.py.\n")
    mtl.append("newmtl fill\nKd 0 0 0\nKe %g %g %g\n" % (radiance, radiance, radiance))
    # The floor (facing up) and the back wall (facing the camera), both dark.
    floor = [(-EXTENT, FLOOR_Y, WALL_Z), (-EXTENT, FLOOR_Y, EXTENT), (EXTENT, FLOOR_Y, EXTENT), (EXTENT, FLOOR_Y, WALL_Z)]
    wall = [(EXTENT, FLOOR_Y, WALL_Z), (EXTENT, EXTENT, WALL_Z), (-EXTENT, EXTENT, WALL_Z), (-EXTENT, FLOOR_Y, WALL_Z)]
    backdrop = Obj()
    backdrop.add_face_group("backdrop", floor + wall, [(0, 1, 2), (0, 2, 3), (4, 5, 6), (4, 6, 7)])
    backdrop.write("backdrop.obj", "# veach-mis: the dark floor and back wall. Generated by make_scene.py.\n")
    mtl.append("newmtl backdrop\nKd 0.1 0.1 0.1\n")
    plates.write("plates.obj", "# veach-mis: four glossy plates, plate_1 nearest the lights. Generated by make_scene.py.\n")
    with open("veach-mis.mtl", "w") as out:
        out.write("\n".join(mtl))


if __name__ == "__main__":
    main()
