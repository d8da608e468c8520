#!/usr/bin/env python3
"""The relMSE of images against a reference made of two independent renders, for measuring any
renderer's error the way `compare` measures FreezeRay's: each renderer against its own reference,
so that two renderers whose pictures differ slightly (texture filtering, a different sampler) are
each judged on their own noise.

  image_error.py --reference A.pfm B.pfm IMAGE.pfm [IMAGE.pfm ...]

The reference is the mean M of A and B (two long renders under seeds that no measured image uses).
Its own noise is estimated from their difference: for independent A and B of equal variance,
(A - B)^2 / 4 estimates the variance of M, so the mean of (A - B)^2 / (4 (M^2 + 0.01)) is M's
relMSE, and it is subtracted from each image's relMSE, as `compare` subtracts its reference's
estimated noise. relMSE is the mean over pixels and channels of
(x - r)^2 / (r^2 + 0.01) (Rousselle, Knaus and Zwicker, "Adaptive Sampling and Reconstruction
using Greedy Error Minimization", 2011), FreezeRay's metric. The reference's noise is printed
too: it should be well below the errors it is used to measure.
"""
import argparse
import sys

from pfm_images import RELATIVE_MSE_EPSILON, read_pfm, relative_mse


def read_same_size(path, size):
    width, height, values = read_pfm(path)
    if size is not None and (width, height) != size:
        sys.exit("%s is %dx%d but the reference is %dx%d" % (path, width, height, size[0], size[1]))
    return (width, height), values


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--reference", nargs=2, required=True, metavar=("A", "B"),
                        help="two independent renders of the reference (PFM)")
    parser.add_argument("images", nargs="+", help="the images to measure (PFM)")
    args = parser.parse_args()

    size, first = read_same_size(args.reference[0], None)
    _, second = read_same_size(args.reference[1], size)
    reference = [(a + b) / 2 for a, b in zip(first, second)]
    noise = sum((a - b) * (a - b) / (4 * (m * m + RELATIVE_MSE_EPSILON))
                for a, b, m in zip(first, second, reference)) / len(reference)
    print("reference: mean of %s and %s, its own relMSE about %.3g" % (args.reference[0], args.reference[1], noise))
    for path in args.images:
        _, image = read_same_size(path, size)
        error = relative_mse(image, reference)
        print("%s: relMSE %.4g (%.4g before the reference's noise is subtracted)" % (path, error - noise, error))


if __name__ == "__main__":
    main()
