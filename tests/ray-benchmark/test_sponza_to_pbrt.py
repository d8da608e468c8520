#!/usr/bin/env python3
"""sponza_to_pbrt.py writes a pbrt-v3 scene of scenes/sponza/scene.json that holds what the book's
side-by-side timing says it holds: every triangle of the OBJ, the scene's camera, textures that
exist, and paths of the same length; and in pbrt-v4's dialect the same, with the JPEG textures,
the alpha masks, the seed, the image file and the size asked for. Exit 77 (skipped) without the
shared scenes.
Usage: test_sponza_to_pbrt.py SOURCE_DIR"""
import json
import os
import re
import subprocess
import sys
import tempfile

source = sys.argv[1]
shared = os.environ.get("FREEZERAY_SHARED_SCENES") or os.path.join(source, "..", "shared", "scenes")
obj = os.path.join(shared, "crytek-sponza", "sponza.obj")
if not os.path.isfile(obj):
    print("skipped: %s is not there (set FREEZERAY_SHARED_SCENES)" % obj)
    sys.exit(77)

failures = 0


def check(name, condition):
    global failures
    print(("ok   [%s]" if condition else "FAIL [%s]") % name)
    failures += 0 if condition else 1


# The OBJ's triangles: a polygon of n corners gives n - 2, however it is cut.
expected_triangles = 0
with open(obj) as f:
    for line in f:
        if line.startswith("f "):
            expected_triangles += len(line.split()) - 3
scene = json.load(open(os.path.join(source, "scenes", "sponza", "scene.json")))

with tempfile.TemporaryDirectory() as work:
    out = os.path.join(work, "sponza.pbrt")
    run = subprocess.run([sys.executable, os.path.join(source, "chapters", "06-kd-tree", "benchmark", "sponza_to_pbrt.py"),
                          "--out", out, "--spp", "3"], capture_output=True, text=True)
    check("the script succeeds", run.returncode == 0)
    if run.returncode != 0:
        print(run.stderr)
        sys.exit(1)
    text = open(out).read()
    check("no partial file is left", os.listdir(work) == ["sponza.pbrt"])
    indices = re.findall(r'"integer indices" \[([^\]]*)\]', text)
    triangles = sum(len(i.split()) for i in indices) // 3
    check("%d triangles, the OBJ's %d" % (triangles, expected_triangles), triangles == expected_triangles)
    camera = scene["camera"]
    look_at = "LookAt %s  %s  %s" % tuple(" ".join(map(str, v)) for v in (camera["position"], camera["look_at"], camera.get("up", [0, 1, 0])))
    check("the scene's camera: " + look_at, look_at in text)
    check("the scene's field of view", '"float fov" %s' % camera["fov_vertical_degrees"] in text)
    check("the scene's resolution", '"integer xresolution" %d "integer yresolution" %d' % tuple(camera["resolution"]) in text)
    check("paths of max_depth segments: maxdepth %d" % (scene["render"]["max_depth"] - 1),
          '"integer maxdepth" %d' % (scene["render"]["max_depth"] - 1) in text)
    check("3 samples per pixel", '"integer pixelsamples" 3' in text)
    textures = re.findall(r'"string filename" "([^"]*)"', text)
    check("%d textures, every one a PNG that exists" % len(textures),
          len(textures) > 0 and all(t.endswith(".png") and os.path.isfile(t) for t in textures))

    # pbrt-v4's dialect.
    out = os.path.join(work, "sponza-v4.pbrt")
    run = subprocess.run([sys.executable, os.path.join(source, "chapters", "06-kd-tree", "benchmark", "sponza_to_pbrt.py"),
                          "--out", out, "--spp", "3", "--pbrt-version", "4", "--seed", "17", "--image", "x.pfm",
                          "--width", "200", "--height", "100", "--texture-filter", "trilinear"],
                         capture_output=True, text=True)
    check("pbrt-v4: the script succeeds", run.returncode == 0)
    if run.returncode != 0:
        print(run.stderr)
        sys.exit(1)
    v4 = open(out).read()
    indices = re.findall(r'"integer indices" \[([^\]]*)\]', v4)
    check("pbrt-v4: the OBJ's triangles", sum(len(i.split()) for i in indices) // 3 == expected_triangles)
    check("pbrt-v4: the same camera", look_at in v4 and '"float fov" %s' % camera["fov_vertical_degrees"] in v4)
    check("pbrt-v4: the size asked for, the image file and the seed",
          'Film "rgb" "integer xresolution" 200 "integer yresolution" 100 "string filename" "x.pfm"' in v4
          and '"integer seed" 17' in v4)
    check("pbrt-v4: its names for positions, texture coordinates and diffuse materials",
          '"point3 P"' in v4 and '"point2 uv"' in v4 and '"point P"' not in v4 and 'Material "diffuse"' in v4
          and '"matte"' not in v4 and "WorldEnd" not in v4)
    images = re.findall(r'"spectrum" "imagemap" "string filename" "([^"]*)" "string filter" "trilinear"', v4)
    check("pbrt-v4: %d colour textures, JPEGs among them, every one a file, filtered as asked" % len(images),
          len(images) > len(textures) and any(t.endswith(".jpg") for t in images)
          and all(os.path.isfile(t) for t in images) and len(images) == v4.count('"spectrum" "imagemap"'))
    mtl = open(os.path.join(shared, "crytek-sponza", "sponza.mtl")).read()
    masks = re.findall(r'"float" "imagemap" "string filename" "([^"]*)"', v4)
    check("pbrt-v4: one alpha texture per map_d of the MTL (%d), each on its mesh" % len(masks),
          len(masks) == len(re.findall(r"^\s*map_d ", mtl, re.M)) > 0
          and v4.count('"texture alpha"') == len(masks) and all(os.path.isfile(t) for t in masks))
sys.exit(1 if failures else 0)
