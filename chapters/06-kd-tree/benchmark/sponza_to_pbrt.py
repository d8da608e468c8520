#!/usr/bin/env python3
"""Writes scenes/sponza/scene.json as a pbrt-v3 or pbrt-v4 scene, so that FreezeRay's rendering
speed and error can be measured against pbrt's path tracer on the same view (book/06-kd-tree.md,
"Against pbrt-v3"; book/11-results.md, "Against pbrt-v4").

  sponza_to_pbrt.py --out sponza.pbrt [--spp N] [--pbrt-version 3|4] [--seed S] [--image FILE]
                    [--texture-filter F] [--width W --height H] [--scene scenes/sponza/scene.json]

What is the same: the triangles (the OBJ's polygons cut into fans: for its planar quads the
surface FreezeRay's loader gives too, with the normals and texture coordinates), the camera
(position, look-at, up, vertical field of view, resolution; pbrt is left-handed, so the world is
mirrored in x first), every material diffuse with its MTL `Kd` or its `map_Kd` (pbrt-v3 reads
no JPEG: for it those three materials get their `Kd`; pbrt-v4 reads them), pbrt-v4 also the
MTL's alpha masks (`map_d`), a white constant sky, a box pixel filter,
and the path length: FreezeRay's `max_depth` counts segments, pbrt's `maxdepth` bounces, so pbrt
gets max_depth - 1 (both then trace paths of at most max_depth segments, with next-event
estimation at every vertex but the last). pbrt keeps its own sampler (pbrt-v3 Halton, pbrt-v4
its default, the Owen-scrambled, Morton-ordered `zsobol`), texture filtering (pbrt-v4's
`--texture-filter trilinear` asks for FreezeRay's, MIP-mapped over the ray's footprint) and BVH.

pbrt is not part of FreezeRay: build it from its own repository (Pharr, Jakob and Humphreys,
"Physically Based Rendering", 3rd edition, 2016, or 4th edition, 2023) and time both renderers
side by side, for example with /usr/bin/time, taking samples per second from each one's spp and
wall time; tools/image_error.py measures each one's error against its own reference."""
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
    """Per material: its Kd (three strings) and its map_Kd and map_d file names, if any."""
    materials, current = {}, None
    with open(path) as mtl:
        for line in mtl:
            words = line.split()
            if not words:
                continue
            if words[0] == "newmtl":
                current = words[1]
                materials[current] = {"Kd": ["0.5", "0.5", "0.5"], "map_Kd": None, "map_d": None}
            elif current is not None and words[0] == "Kd":
                materials[current]["Kd"] = words[1:4]
            elif current is not None and words[0] in ("map_Kd", "map_d"):
                materials[current][words[0]] = words[1]
    return materials


def write_mesh(out, triangles, positions, uvs, normals, version, alpha=None):
    """One trianglemesh: each (v, vt, vn) corner becomes one pbrt vertex; `alpha`, the name of a
    float texture that cuts it out."""
    index_of, corners, indices = {}, [], []
    for triangle in triangles:
        for corner in triangle:
            if corner not in index_of:
                index_of[corner] = len(corners)
                corners.append(corner)
            indices.append(index_of[corner])
    out.write('Shape "trianglemesh"\n  "integer indices" [%s]\n' % " ".join(map(str, indices)))
    if alpha is not None:
        out.write('  "texture alpha" "%s"\n' % alpha)
    out.write('  "%s P" [%s]\n' % ("point" if version == 3 else "point3",
                                    " ".join(" ".join(positions[c[0]]) for c in corners)))
    if all(c[1] >= 0 for c in corners):
        out.write('  "%s uv" [%s]\n' % ("float" if version == 3 else "point2",
                                      " ".join(" ".join(uvs[c[1]]) for c in corners)))
    if all(c[2] >= 0 for c in corners):
        out.write('  "normal N" [%s]\n' % " ".join(" ".join(normals[c[2]]) for c in corners))


def main():
    repository = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", ".."))
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scene", default=os.path.join(repository, "scenes", "sponza", "scene.json"))
    parser.add_argument("--out", required=True, help="the pbrt scene file to write")
    parser.add_argument("--spp", type=int, default=16, help="samples per pixel (default 16)")
    parser.add_argument("--pbrt-version", type=int, choices=(3, 4), default=3,
                        help="the scene format, pbrt-v3's or pbrt-v4's (default 3)")
    parser.add_argument("--seed", type=int, help="pbrt-v4: the sampler's seed (default: pbrt's)")
    parser.add_argument("--image", help="pbrt-v4: the image file pbrt writes (default: pbrt's)")
    parser.add_argument("--texture-filter", choices=("point", "bilinear", "trilinear", "ewa"),
                        help="pbrt-v4: the colour textures' filter (default: pbrt's)")
    parser.add_argument("--width", type=int, help="image width (default: the scene's)")
    parser.add_argument("--height", type=int, help="image height (default: the scene's)")
    args = parser.parse_args()
    if args.pbrt_version == 3 and (args.seed is not None or args.image is not None or args.texture_filter):
        sys.exit("--seed, --image and --texture-filter are written for pbrt-v4 only")

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
    width, height = args.width or width, args.height or height
    scene["camera"]["resolution"] = [width, height]
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
    print("%s: pbrt-v%d, %d triangles, %d materials, %dx%d, %d spp, pbrt maxdepth %d"
          % (args.out, args.pbrt_version, sum(len(t) for t in groups.values()), len(groups), width, height,
             args.spp, scene["render"]["max_depth"] - 1))


def write_scene(path, args, scene, repository, groups, materials, positions, uvs, normals, obj_folder):
    camera = scene["camera"]
    width, height = camera["resolution"]
    render = scene["render"]
    with open(path, "w") as out:
        out.write("# Written by chapters/06-kd-tree/benchmark/sponza_to_pbrt.py from %s\n" % os.path.relpath(args.scene, repository))
        out.write("Scale -1 1 1\n")  # pbrt's camera space is left-handed, FreezeRay's right-handed
        out.write("LookAt %s  %s  %s\n" % tuple(" ".join(map(str, v)) for v in (camera["position"], camera["look_at"], camera.get("up", [0, 1, 0]))))
        out.write('Camera "perspective" "float fov" %s\n' % camera["fov_vertical_degrees"])
        v4 = args.pbrt_version == 4
        if v4:
            out.write('Film "rgb" "integer xresolution" %d "integer yresolution" %d' % (width, height))
            out.write(' "string filename" "%s"\n' % args.image if args.image else "\n")
            out.write('PixelFilter "box"\n')
            out.write('Sampler "zsobol" "integer pixelsamples" %d' % args.spp)
            out.write(' "integer seed" %d\n' % args.seed if args.seed is not None else "\n")
        else:
            out.write('Film "image" "integer xresolution" %d "integer yresolution" %d\n' % (width, height))
            out.write('PixelFilter "box"\n')
            out.write('Sampler "halton" "integer pixelsamples" %d\n' % args.spp)
        out.write('Integrator "path" "integer maxdepth" %d\n' % (render["max_depth"] - 1))
        out.write('WorldBegin\nAttributeBegin\nLightSource "infinite" "rgb L" [1 1 1]\nAttributeEnd\n')
        reads = (".png", ".jpg", ".jpeg") if v4 else (".png",)
        for index, (name, triangles) in enumerate(groups.items()):
            material = materials.get(name, {"Kd": ["0.5", "0.5", "0.5"], "map_Kd": None, "map_d": None})
            texture = material["map_Kd"]
            if texture is not None and texture.lower().endswith(reads):
                out.write('Texture "kd%d" "spectrum" "imagemap" "string filename" "%s"'
                          % (index, os.path.join(obj_folder, texture)))
                out.write(' "string filter" "%s"\n' % args.texture_filter if args.texture_filter else "\n")
                out.write('Material "diffuse" "texture reflectance" "kd%d"\n' % index if v4 else
                          'Material "matte" "texture Kd" "kd%d"\n' % index)
            else:
                out.write('Material "%s" "rgb %s" [%s]\n' % ("diffuse" if v4 else "matte",
                                                           "reflectance" if v4 else "Kd", " ".join(material["Kd"])))
            # pbrt-v4 cuts out by the MTL's map_d as FreezeRay does (its alpha test keeps a point
            # with probability alpha; the masks are 0 or 1 but at their edges' texels).
            alpha = None
            if v4 and material["map_d"] is not None:
                alpha = "alpha%d" % index
                out.write('Texture "%s" "float" "imagemap" "string filename" "%s" "string encoding" "linear"\n'
                          % (alpha, os.path.join(obj_folder, material["map_d"])))
            write_mesh(out, triangles, positions, uvs, normals, args.pbrt_version, alpha)
        if not v4:
            out.write("WorldEnd\n")  # pbrt-v4's scene ends with its file


if __name__ == "__main__":
    main()
