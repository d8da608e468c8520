#!/usr/bin/env python3
"""Writes lanterns.obj and lanterns.mtl (run from this folder): the small spherical lamps that
light Sponza at night (night.json). Many small area lights under a night sky are the lighting of
the comparison of path tracing, bidirectional path tracing and Metropolis light transport on
real scenes.

Each lantern is an icosphere of radius 8 cm (80 triangles, every one an area light of its own),
hung in the open: six along the middle of the court, four in each ground-floor arcade, and one
above each of the four hanging vases at the court's corners. Positions are in Sponza's frame
(centimetres, y up, the court running along x between z = -230 and z = 150). The material is a
diffuse white; night.json gives it its emission."""
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ in scenes/tools
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tools"))
from meshes import ObjBuilder, icosphere  # noqa: E402

RADIUS = 8.0
COURT = [(x, 350.0, -40.0) for x in (-1100.0, -700.0, -300.0, 100.0, 500.0, 900.0)]
ARCADES = [(x, 250.0, z) for z in (-420.0, 340.0) for x in (-1000.0, -400.0, 200.0, 800.0)]
OVER_VASES = [(x, 260.0, z) for x in (-619.0, 476.0) for z in (-220.0, 144.0)]
LANTERNS = COURT + ARCADES + OVER_VASES


def main():
    unit_vertices, faces = icosphere(1)
    obj = ObjBuilder(mtllib="lanterns.mtl", decimals=4)
    for centre in LANTERNS:
        vertices = [tuple(c + RADIUS * v for c, v in zip(centre, u)) for u in unit_vertices]
        obj.add("lantern", vertices, faces)
    with open("lanterns.mtl", "w") as out:
        out.write("# Written by make_lanterns.py; night.json gives the lanterns their emission\n"
                  "newmtl lantern\nKd 0.8 0.8 0.8\n")
    obj.write("lanterns.obj", "# Written by make_lanterns.py: %d lanterns of radius %g cm, 80 triangles each\n"
              % (len(LANTERNS), RADIUS))


if __name__ == "__main__":
    main()
