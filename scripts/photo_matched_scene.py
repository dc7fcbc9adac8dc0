#!/usr/bin/env python3
"""Turns a `phellem fit` result into a photo-matched scene (a maintenance script for the
examples in scenes/ and docs/, not part of the build or the tests).

    scripts/photo_matched_scene.py FIT_DIR NAME ALBEDO HEIGHT > scenes/fitted_NAME.json

The fitted bark keeps every fitted parameter; the scene adds the default scene's daylight
(the builtin Rooitou Park HDRI, and its sun moved in front of the trunk), the photo's colours through the dressing's
`photo` key, and a camera that frames about 51 cm of bark square-on at 512×512 px, about
10 px/cm like the scans, so the render stands beside the photograph at the same scale.
"""
import json
import sys

fit_dir, name, albedo, height = sys.argv[1:5]
scene = json.load(open(f"{fit_dir}/fitted.json"))
default = json.load(open("scenes/default.json"))
trunk = next(o for o in scene["objects"] if o["type"] == "tree")
bark = trunk["bark"]
dressing = bark.setdefault("dressing", {})
dressing["photo"] = {"albedo": albedo, "height": height, "px_per_cm": 10}
dressing.setdefault("relief", {"depth_ratio": 1.2, "detail": 0.6})
dressing["roughness"] = {"ridge": 0.85, "fissure": 0.6, "noise": 0.2}
dressing["depth_darkening"] = 0.15
# A straight trunk of 30 cm radius, seen square-on from 0.95 m: a 30° field of view spans 51 cm.
trunk["axis"] = [[0, -0.05, 0], [0, 2.0, 0]]
trunk["radius"] = [0.3, 0.3]
scene["camera"] = {"position": [0.0, 1.0, 1.25], "look_at": [0.0, 1.0, 0.0], "fov_deg": 30}
scene["render"] = {"resolution": [512, 512], "spp": 32, "max_depth": 6, "seed": 11}
# The default scene's sky, but its sun from over the camera's right shoulder: the scans' albedo
# is lit flat, and the default sun, grazing from the side, left the fitted relief's plates in
# their own shadow (mean 43/255 against 84 with this sun).
scene["lights"] = default["lights"]
for light in scene["lights"]:
    if light["type"] == "sun":
        light["direction"] = [0.45, 0.45, 0.77]
scene["objects"] = [trunk]
json.dump(scene, sys.stdout, indent=1)
sys.stdout.write("\n")
