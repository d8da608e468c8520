"""Colour PFM images as the project's Python tools read and compare them: the pixels as one flat
list of floats, and FreezeRay's error metric (common/core/src/metrics.cpp)."""
import struct
import sys

# relMSE's epsilon: the mean of (x - r)^2 / (r^2 + RELATIVE_MSE_EPSILON) (Rousselle, Knaus and
# Zwicker, "Adaptive Sampling and Reconstruction using Greedy Error Minimization", 2011).
RELATIVE_MSE_EPSILON = 1e-2


def read_pfm(path):
    """Returns (width, height, list of floats RGB) of a colour PFM file."""
    with open(path, "rb") as f:
        if f.readline().strip() != b"PF":
            sys.exit(f"{path}: not a colour PFM file")
        width, height = map(int, f.readline().split())
        scale = float(f.readline())
        data = f.read()
    order = "<" if scale < 0 else ">"
    return width, height, struct.unpack(f"{order}{width * height * 3}f", data[: width * height * 12])


def relative_mse(image, reference):
    """The mean over pixels and channels of (x - r)^2 / (r^2 + epsilon)."""
    return sum((x - r) * (x - r) / (r * r + RELATIVE_MSE_EPSILON) for x, r in zip(image, reference)) / len(reference)
