#!/usr/bin/env python3
"""Writes scenes/sponza/scene.json as a pbrt-v3 scene, so that chapter 06's rendering speed can be
measured against pbrt-v3's path tracer on the same view (book/06-kd-tree.md, "Measuring").

  sponza_to_pbrt.py --out sponza.pbrt [--spp N] [--scene scenes/sponza/scene.json]

What is the same: the triangles (the OBJ's polygons cut into fans: for its planar quads the
surface FreezeRay's loader gives too, with the normals and texture coordinates), the camera
(position, look-at, up, vertical field of view, resolution; pbrt is left-handed, so the world is
mirrored in x first), every material diffuse with its MTL `Kd` or its PNG `map_Kd` (pbrt-v3 reads no JPEG: those three materials get their `Kd`), a white constant
sky, a box pixel filter, and the path length: FreezeRay's `max_depth` counts segments, pbrt's
`maxdepth` bounces, so pbrt gets max_depth - 1 (both then trace paths of at most max_depth
segments, with next-event estimation at every vertex but the last). pbrt-v3 keeps its own
sampler (Halton), texture filtering and BVH.

pbrt-v3 itself is not part of FreezeRay: build it from its own repository (Pharr, Jakob and
Humphreys, "Physically Based Rendering", 3rd edition, 2016) and time both renderers side by side,
for example with /usr/bin/time, taking samples per second from each one's spp and wall time."""
import argparse
import json
import os
import sys

SHARED_PREFIX = "$FREEZERAY_SHARED_SCENES/"


def shared_scenes_folder(repository):
    return os.environ.get("FREEZERAY_SHARED_SCENES") or os.path.join(repository, "..", "shared", "scenes")


def resolve(name, scene_folder, repository):
    if name.startswith(SHARED_PREFIX):
        return os.path.normpath(os.path.join(shared_scenes_folder(repository), name[len(SHARED_PREFIX):]))
    return os.path.normpath(os.path.join(scene_folder, name))


def read_obj(path):
    """Positions, texture coordinates, normals and, per material, triangles of (v, vt, vn)
    index triples (0-based; -1 where the file gives none), polygons fan-triangulated."""
    positions, uvs, normals, groups = [], [], [], {}
    material = None
    with open(path) as obj:
        for number, line in enumerate(obj, 1):
            words = line.split()
            if not words:
                continue
            if words[0] == "v":
                positions.append(words[1:4])
            elif words[0] == "vt":
                uvs.append(words[1:3])
            elif words[0] == "vn":
                normals.append(words[1:4])
            elif words[0] == "usemtl":
                material = words[1]
            elif words[0] == "f":
                corners = []
                for corner in words[1:]:
                    fields = (corner.split("/") + ["", ""])[:3]
                    corners.append(tuple(int(f) - 1 if f else -1 for f in fields))
                if any(c[0] < 0 for c in corners):
                    sys.exit("%s:%d: relative (negative) face indices are not supported" % (path, number))
                triangles = groups.setdefault(material, [])
                for i in range(1, len(corners) - 1):
                    triangles.append((corners[0], corners[i], corners[i + 1]))
    return positions, uvs, normals, groups


def read_mtl(path):
    """Per material: its Kd (three strings) and its map_Kd file name, if any."""
    materials, current = {}, None
    with open(path) as mtl:
        for line in mtl:
            words = line.split()
            if not words:
                continue
            if words[0] == "newmtl":
                current = words[1]
                materials[current] = {"Kd": ["0.5", "0.5", "0.5"], "map_Kd": None}
            elif current is not None and words[0] == "Kd":
                materials[current]["Kd"] = words[1:4]
            elif current is not None and words[0] == "map_Kd":
                materials[current]["map_Kd"] = words[1]
    return materials


def write_mesh(out, triangles, positions, uvs, normals):
    """One trianglemesh: each (v, vt, vn) corner becomes one pbrt vertex."""
    index_of, corners, indices = {}, [], []
    for triangle in triangles:
        for corner in triangle:
            if corner not in index_of:
                index_of[corner] = len(corners)
                corners.append(corner)
            indices.append(index_of[corner])
    out.write('Shape "trianglemesh"\n  "integer indices" [%s]\n' % " ".join(map(str, indices)))
    out.write('  "point P" [%s]\n' % " ".join(" ".join(positions[c[0]]) for c in corners))
    if all(c[1] >= 0 for c in corners):
        out.write('  "float uv" [%s]\n' % " ".join(" ".join(uvs[c[1]]) for c in corners))
    if all(c[2] >= 0 for c in corners):
        out.write('  "normal N" [%s]\n' % " ".join(" ".join(normals[c[2]]) for c in corners))


def main():
    repository = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", ".."))
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scene", default=os.path.join(repository, "scenes", "sponza", "scene.json"))
    parser.add_argument("--out", required=True, help="the pbrt-v3 scene file to write")
    parser.add_argument("--spp", type=int, default=16, help="samples per pixel (default 16)")
    args = parser.parse_args()

    with open(args.scene) as f:
        scene = json.load(f)
    folder = os.path.dirname(os.path.abspath(args.scene))
    if len(scene["meshes"]) != 1 or scene["lights"] != [{"type": "constant", "radiance": [1, 1, 1]}]:
        sys.exit("%s: only one mesh under a white constant sky is translated" % args.scene)
    obj_path = resolve(scene["meshes"][0]["file"], folder, repository)
    if not os.path.isfile(obj_path):
        sys.exit("%s is not there (set FREEZERAY_SHARED_SCENES)" % obj_path)
    obj_folder = os.path.dirname(obj_path)
    positions, uvs, normals, groups = read_obj(obj_path)
    materials = read_mtl(os.path.join(obj_folder, os.path.splitext(os.path.basename(obj_path))[0] + ".mtl"))

    width, height = scene["camera"].setdefault("resolution", [256, 256])
    if width < height:  # pbrt's fov spans the shorter side, FreezeRay's the height
        sys.exit("%s: a portrait image is not translated" % args.scene)
    temporary = args.out + ".partial"
    try:
        write_scene(temporary, args, scene, repository, groups, materials, positions, uvs, normals, obj_folder)
    except BaseException:
        if os.path.exists(temporary):
            os.remove(temporary)  # nothing half-written is left
        raise
    os.replace(temporary, args.out)
    print("%s: %d triangles, %d materials, %dx%d, %d spp, pbrt maxdepth %d"
          % (args.out, sum(len(t) for t in groups.values()), len(groups), scene["camera"]["resolution"][0],
             scene["camera"]["resolution"][1], args.spp, scene["render"]["max_depth"] - 1))


def write_scene(path, args, scene, repository, groups, materials, positions, uvs, normals, obj_folder):
    camera = scene["camera"]
    width, height = camera["resolution"]
    render = scene["render"]
    with open(path, "w") as out:
        out.write("# Written by chapters/06-kd-tree/benchmark/sponza_to_pbrt.py from %s\n" % os.path.relpath(args.scene, repository))
        out.write("Scale -1 1 1\n")  # pbrt's camera space is left-handed, FreezeRay's right-handed
        out.write("LookAt %s  %s  %s\n" % tuple(" ".join(map(str, v)) for v in (camera["position"], camera["look_at"], camera.get("up", [0, 1, 0]))))
        out.write('Camera "perspective" "float fov" %s\n' % camera["fov_vertical_degrees"])
        out.write('Film "image" "integer xresolution" %d "integer yresolution" %d\n' % (width, height))
        out.write('PixelFilter "box"\n')
        out.write('Sampler "halton" "integer pixelsamples" %d\n' % args.spp)
        out.write('Integrator "path" "integer maxdepth" %d\n' % (render["max_depth"] - 1))
        out.write('WorldBegin\nAttributeBegin\nLightSource "infinite" "rgb L" [1 1 1]\nAttributeEnd\n')
        for index, (name, triangles) in enumerate(groups.items()):
            material = materials.get(name, {"Kd": ["0.5", "0.5", "0.5"], "map_Kd": None})
            texture = material["map_Kd"]
            if texture is not None and texture.lower().endswith(".png"):
                out.write('Texture "kd%d" "spectrum" "imagemap" "string filename" "%s"\n'
                          % (index, os.path.join(obj_folder, texture)))
                out.write('Material "matte" "texture Kd" "kd%d"\n' % index)
            else:
                out.write('Material "matte" "rgb Kd" [%s]\n' % " ".join(material["Kd"]))
            write_mesh(out, triangles, positions, uvs, normals)
        out.write("WorldEnd\n")


if __name__ == "__main__":
    main()
