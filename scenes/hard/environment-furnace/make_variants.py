#!/usr/bin/env python3
"""Writes the environment furnaces (run from this folder): each lossless case of ../white-furnace/
with the emitting enclosure replaced by a constant environment of radiance 1 (the classic white
furnace). Same object, same material, same camera; every path that leaves the object escapes to
the environment with weight 1, so every pixel is exactly 1."""
import json

# The white-furnace cases whose object absorbs nothing (the lossy ones are at most 1 there).
LOSSLESS = {
    "scene": "white diffuse of albedo 1",
    "mirror": "a mirror of reflectance 1",
    "dielectric": "smooth glass of index 1.5",
    "dielectric-ior-0.67": "smooth glass of index 0.67",
    "dielectric-index-matched": "index-matched smooth glass (eta 1)",
    "rough-dielectric-index-matched": "index-matched rough glass (eta 1, roughness 0.5)",
    "plastic": "smooth plastic with a white base",
    "mix": "a mix of white diffuse and mirror",
    "glass-cube": "a glass cube of index 1.5, totally reflecting inside",
}

for name, what in LOSSLESS.items():
    with open("../white-furnace/%s.json" % name) as f:
        scene = json.load(f)
    scene["description"] = (
        "The classic white furnace: %s (the object of white-furnace/%s.json) under a constant environment of radiance 1 "
        "instead of the emitting enclosure. Every path escapes to the environment with weight 1, so every pixel, the "
        "silhouette's grazing pixels included, is exactly 1. Stresses: light sampling of the environment (pt-nee, pt-mis) "
        "against the object's lobes, the environment added on escape (pt-naive, pt-is). Asserted: no invalid sample; every "
        "16x16 block, the silhouette and the object pixels equal 1 (one-sample t-tests) for pt-is, pt-nee and pt-mis%s. "
        "Written by make_variants.py." % (what, name, " and pt-naive" if name == "scene" else ""))
    scene["chapter"] = 3
    scene["meshes"] = [m for m in scene["meshes"] if m.get("material") != "furnace_wall"]
    del scene["materials"]["furnace_wall"]
    scene["lights"] = [{"type": "constant", "radiance": 1}]
    scene["render"] = {"integrator": "pt-mis", "spp": 64, "seed": 0}
    out_name = "diffuse" if name == "scene" else name
    with open(out_name + ".json", "w") as out:
        json.dump(scene, out, indent=2)
        out.write("\n")
