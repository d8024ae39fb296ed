#!/usr/bin/env python3
"""The deformed radius of a standing cylinder, node layer by node layer.

Reads the last field output of a run (OUTPUT/solution.pvd and its .vtu
pieces, through hertz_profile.read_vtu) and, for the points of the cells
of material id --material (the rubber), groups them by their reference
height z and prints, for each layer, the largest deformed radius
sqrt((X + u_x)^2 + (Y + u_y)^2) against the radius of a homogeneous
compression of an incompressible cylinder to the same height,
R / sqrt(lambda), lambda = (current height) / (reference height), the
current height being the mean z of the top layer minus that of the bottom
layer. With --bound B, exits 1 if a layer's radius departs from R /
sqrt(lambda) by more than B (relative).

Usage: radius_profile.py OUTPUT_DIRECTORY --radius R [--material ID]
       [--bound B]
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from hertz_profile import last_field_output, read_vtu  # noqa: E402


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("output")
    parser.add_argument("--radius", type=float, required=True)
    parser.add_argument("--material", type=float, default=1.)
    parser.add_argument("--bound", type=float, default=None)
    args = parser.parse_args()

    time, pieces = last_field_output(args.output)
    layers = {}
    for piece in pieces:
        points, data = read_vtu(piece)
        for X, u, m in zip(points, data["displacement"], data["material_id"]):
            if abs(m - args.material) > 0.5:
                continue
            z = round(X[2], 6)
            radius = ((X[0] + u[0]) ** 2 + (X[1] + u[1]) ** 2) ** 0.5
            layer = layers.setdefault(z, {"radius": 0., "z": []})
            layer["radius"] = max(layer["radius"], radius)
            layer["z"].append(X[2] + u[2])
    heights = sorted(layers)
    mean = lambda v: sum(v) / len(v)
    height = mean(layers[heights[-1]]["z"]) - mean(layers[heights[0]]["z"])
    stretch = height / (heights[-1] - heights[0])
    homogeneous = args.radius / stretch ** 0.5
    print("t = %g ms: lambda = %.5f, R / sqrt(lambda) = %.4f mm"
          % (time, stretch, homogeneous))
    worst = 0.
    for z in heights:
        deviation = layers[z]["radius"] / homogeneous - 1.
        worst = max(worst, abs(deviation))
        print("  layer Z = %6.2f mm: largest radius %.4f mm (%+.2f %%)"
              % (z, layers[z]["radius"], 100. * deviation))
    print("largest deviation %.2f %%" % (100. * worst))
    if args.bound is not None and worst > args.bound:
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
