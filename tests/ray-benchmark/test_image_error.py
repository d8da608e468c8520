#!/usr/bin/env python3
"""tools/image_error.py on images whose errors are known exactly: the reference is the mean of its
two halves, its noise is a quarter of their relMSE, and each image's relMSE is measured against
the mean with that noise subtracted; images of another size are refused with both sizes.
Usage: test_image_error.py SOURCE_DIR"""
import os
import re
import struct
import subprocess
import sys
import tempfile

source = sys.argv[1]
failures = 0


def check(name, condition):
    global failures
    print(("ok   [%s]" if condition else "FAIL [%s]") % name)
    failures += 0 if condition else 1


def write_pfm(path, width, height, values):
    with open(path, "wb") as f:
        f.write(b"PF\n%d %d\n-1\n" % (width, height))
        f.write(struct.pack("<%df" % len(values), *values))


with tempfile.TemporaryDirectory() as work:
    # Two pixels; every channel of A is 1 and of B is 3, so the reference is 2.
    a = [1.0] * 6
    b = [3.0] * 6
    image = [3.5] * 6
    paths = {name: os.path.join(work, name + ".pfm") for name in ("a", "b", "image", "small")}
    write_pfm(paths["a"], 2, 1, a)
    write_pfm(paths["b"], 2, 1, b)
    write_pfm(paths["image"], 2, 1, image)
    write_pfm(paths["small"], 1, 1, [2.0] * 3)
    tool = os.path.join(source, "tools", "image_error.py")
    run = subprocess.run([sys.executable, tool, "--reference", paths["a"], paths["b"], paths["image"]],
                         capture_output=True, text=True)
    check("the tool succeeds", run.returncode == 0)
    noise = (1.0 - 3.0) ** 2 / (4 * (2.0 ** 2 + 0.01))  # (A - B)^2 / 4 estimates the mean's variance
    error = (3.5 - 2.0) ** 2 / (2.0 ** 2 + 0.01)
    printed = re.search(r"relMSE ([-0-9.e]+) \(([-0-9.e]+) before", run.stdout)
    check("the image's relMSE against the mean, %.4g, less the reference's noise, %.4g" % (error, noise),
          printed is not None and abs(float(printed.group(2)) - error) < 1e-3 * error
          and abs(float(printed.group(1)) - (error - noise)) < 1e-3 * abs(error - noise))
    run = subprocess.run([sys.executable, tool, "--reference", paths["a"], paths["b"], paths["small"]],
                         capture_output=True, text=True)
    check("an image of another size is refused with both sizes",
          run.returncode != 0 and "1x1" in run.stderr and "2x1" in run.stderr)
sys.exit(1 if failures else 0)
