#!/usr/bin/env python3
"""Contact pressure profile of a Hertz benchmark against Johnson's closed form.

Reads the last field output of a run (OUTPUT/solution.pvd, deal.II's .vtu
pieces) and its time history (OUTPUT/time_history.csv), and compares the
nodal mortar pressure 'contact_pressure' on the slave surface with Hertz's
profile (K. L. Johnson, Contact Mechanics, Cambridge 1985, chapter 4):

  cylinder (line contact, load P' per unit length):
      b = sqrt(4 P' R / (pi E*)),    p0 = 2 P' / (pi b)
  sphere (point contact, load P):
      a = (3 P R / (4 E*))^(1/3),    p0 = 3 P / (2 pi a^2)
  profile  p(r) = p0 sqrt(1 - (r / b)^2) for r < b, 0 beyond (b: the
  half-width or the radius a), 1 / E* = (1 - nu1^2) / E1 + (1 - nu2^2) / E2.

The load is measured: P' (or P) is minus the reaction column of the
displacement condition that pushes the indenter, times the symmetry factor
(cylinder: a half slice of thickness t on the plane x = 0 carries P' t / 2,
so P' = -2 F / t; quarter sphere on x = 0 and y = 0: P = -4 F).

Positions are the current ones (reference + displacement of the last
output), projected onto the contact plane (normal to the load axis):
r = |x| for the cylinder (the contact plane x-z), r = sqrt(x^2 + y^2) for
the sphere. The slave nodes and facets are those of the physical surface
--slave-id of the Gmsh mesh, matched to the .vtu points by their reference
position.

Checks (exit status 1 if one fails):
  - the half-width b_h within one slave element of Johnson's b: b_h is
    the middle between the farthest slave node with a positive pressure
    and the nearest one without (the edge lies between them), h the
    largest edge of a slave facet within r <= b, projected (for the
    cylinder: along x);
  - the L2 error of the profile
        e = ||p_h - p||_{L2(S)} / (p0 sqrt(A_c)),
    S the slave surface projected onto the contact plane, p_h the bilinear
    interpolation of the nodal pressures on each facet, A_c the modelled
    part of Johnson's contact area (cylinder: b t, quarter sphere:
    pi a^2 / 4), at most --l2-tolerance. (For the cylinder this is the 1D
    norm sqrt(int_0^X (p_h - p)^2 dx / b) / p0.) The integral takes 6 x 6
    Gauss points per facet.
It prints the profile (r, p_h, Johnson's p), the peak nodal pressure
against p0 (information: the history's <pair>_max_pressure is checked by the
calling script), and the errors. Standard library only.

Usage: hertz_profile.py --geometry cylinder|sphere --output DIR
         --mesh MESH.msh --slave-id ID --load-column NAME --radius R
         --young E1,E2 --poisson NU1,NU2 [--l2-tolerance 0.05]
"""

import argparse
import base64
import csv
import math
import os
import struct
import sys
import xml.etree.ElementTree as ElementTree
import zlib


# ---- Reading deal.II's .vtu (XML, inline 'binary' or 'ascii' arrays).
# What rubberdyn writes (postprocess::FieldOutput, deal.II 9.4's
# DataOut::write_vtu_with_pvtu_record with the default VtkFlags): one .vtu
# per rank, indexed by solution_NNNN.pvtu, the times in solution.pvd;
# compressor="vtkZLibDataCompressor", every DataArray format="binary"
# (base64 of zlib blocks, UInt32 header), Float32 points and fields; each
# cell's 8 vertices written on their own (shared nodes repeated), at their
# reference positions; every field (nodal or per cell) as PointData. The
# reader also takes uncompressed, multi-block, UInt64-header and ascii
# arrays.

def _unpack(vtk_type, raw):
    formats = {"Float32": "f", "Float64": "d", "Int32": "i", "Int64": "q",
               "UInt8": "B", "UInt32": "I", "UInt64": "Q", "Int8": "b"}
    if vtk_type not in formats:
        raise ValueError("unsupported DataArray type " + vtk_type)
    code = formats[vtk_type]
    n = len(raw) // struct.calcsize(code)
    return list(struct.unpack("<%d%s" % (n, code), raw[:n * struct.calcsize(code)]))


def _decode_binary(text, vtk_type, compressed, header_type):
    """An inline base64 array of VTK's XML format. Compressed (zlib): the
    header [n_blocks, block_size, last_block_size, compressed sizes...] is
    encoded on its own, then the compressed blocks; uncompressed: one
    base64 string of [n_bytes] and the data."""
    text = "".join(text.split())
    word = 8 if header_type == "UInt64" else 4
    code = "<Q" if word == 8 else "<I"
    if not compressed:
        raw = base64.b64decode(text)
        n_bytes = struct.unpack(code, raw[:word])[0]
        return _unpack(vtk_type, raw[word:word + n_bytes])
    # The first word (n_blocks) is in the first ceil(word / 3) * 4 characters.
    first = base64.b64decode(text[:4 * ((word + 2) // 3)])
    n_blocks = struct.unpack(code, first[:word])[0]
    header_bytes = word * (3 + n_blocks)
    header_chars = 4 * ((header_bytes + 2) // 3)
    header = base64.b64decode(text[:header_chars])
    words = struct.unpack("<%d%s" % (3 + n_blocks, code[1]), header[:header_bytes])
    sizes = words[3:]
    data = base64.b64decode(text[header_chars:])
    raw = b""
    offset = 0
    for size in sizes:
        raw += zlib.decompress(data[offset:offset + size])
        offset += size
    return _unpack(vtk_type, raw)


def read_vtu(path):
    """Points (reference positions) and point-data arrays of one .vtu."""
    root = ElementTree.parse(path).getroot()
    compressed = root.get("compressor") is not None
    header_type = root.get("header_type", "UInt32")
    if root.get("byte_order", "LittleEndian") != "LittleEndian":
        raise ValueError(path + ": big-endian data not supported")
    piece = root.find("UnstructuredGrid/Piece")

    def values(array):
        fmt = array.get("format")
        if fmt == "ascii":
            return [float(v) for v in array.text.split()]
        if fmt == "binary":
            return _decode_binary(array.text, array.get("type"), compressed,
                                  header_type)
        raise ValueError(path + ": DataArray format '%s' not supported" % fmt)

    n_points = int(piece.get("NumberOfPoints"))
    coordinates = values(piece.find("Points/DataArray"))
    points = [tuple(coordinates[3 * i:3 * i + 3]) for i in range(n_points)]
    data = {}
    for array in piece.findall("PointData/DataArray"):
        n_components = int(array.get("NumberOfComponents", "1"))
        v = values(array)
        if n_components == 1:
            data[array.get("Name")] = v
        else:
            data[array.get("Name")] = [tuple(v[n_components * i:n_components * (i + 1)])
                                       for i in range(n_points)]
    return points, data


def last_field_output(directory):
    """The .vtu pieces of the last entry of solution.pvd."""
    pvd = os.path.join(directory, "solution.pvd")
    datasets = ElementTree.parse(pvd).getroot().findall("Collection/DataSet")
    if not datasets:
        raise ValueError(pvd + ": no data set")
    last = max(datasets, key=lambda d: float(d.get("timestep")))
    pvtu = os.path.join(directory, last.get("file"))
    pieces = ElementTree.parse(pvtu).getroot().findall("PUnstructuredGrid/Piece")
    return float(last.get("timestep")), [os.path.join(directory, p.get("Source"))
                                         for p in pieces]


# ---- Reading the slave surface from the Gmsh mesh (MSH 2.2 ASCII).

def read_slave_facets(path, slave_id):
    """Positions of the quadrangles tagged slave_id (their 4 nodes each)."""
    nodes = {}
    facets = []
    with open(path) as f:
        lines = iter(f.read().split("\n"))
    for line in lines:
        if line == "$Nodes":
            for _ in range(int(next(lines))):
                p = next(lines).split()
                nodes[int(p[0])] = tuple(float(x) for x in p[1:4])
        elif line == "$Elements":
            for _ in range(int(next(lines))):
                p = [int(x) for x in next(lines).split()]
                element_type, n_tags = p[1], p[2]
                if element_type == 3 and p[3] == slave_id:
                    facets.append(p[3 + n_tags:3 + n_tags + 4])
    if not facets:
        raise ValueError("%s: no quadrangle with the physical tag %d" % (path, slave_id))
    return [[nodes[v] for v in facet] for facet in facets]


class PointLocator:
    """The .vtu points by position, binned at a resolution of 1e-4 mm (the
    .vtu positions are Float32, ~1e-6 mm off for coordinates of ~10 mm)."""

    def __init__(self, points, resolution=1e-4):
        self.resolution = resolution
        self.points = points
        self.bins = {}
        for i, x in enumerate(points):
            self.bins.setdefault(self.key(x), []).append(i)

    def key(self, x):
        return tuple(int(math.floor(c / self.resolution)) for c in x)

    def find(self, x):
        k = self.key(x)
        best, best_distance = None, self.resolution
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for dz in (-1, 0, 1):
                    for i in self.bins.get((k[0] + dx, k[1] + dy, k[2] + dz), []):
                        d = math.dist(self.points[i], x)
                        if d < best_distance:
                            best, best_distance = i, d
        return best


# ---- The comparison.

def gauss_points(n):
    """Gauss-Legendre points and weights on [0, 1] (Newton on P_n)."""
    points = []
    for i in range(1, n + 1):
        x = math.cos(math.pi * (i - 0.25) / (n + 0.5))
        for _ in range(100):
            p0, p1 = 1.0, x
            for k in range(2, n + 1):
                p0, p1 = p1, ((2 * k - 1) * x * p1 - (k - 1) * p0) / k
            dp = n * (x * p1 - p0) / (x * x - 1)
            dx = p1 / dp
            x -= dx
            if abs(dx) < 1e-15:
                break
        points.append(((1 - x) / 2, 1 / ((1 - x * x) * dp * dp)))
    return points


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--geometry", choices=["cylinder", "sphere"], required=True)
    parser.add_argument("--output", required=True, help="the run's output directory")
    parser.add_argument("--mesh", required=True, help="the Gmsh mesh (.msh 2.2)")
    parser.add_argument("--slave-id", type=int, required=True,
                        help="physical surface tag of the slave faces")
    parser.add_argument("--load-column", required=True,
                        help="reaction column of the pushing condition, e.g. press_force_y")
    parser.add_argument("--radius", type=float, required=True, help="R (mm)")
    parser.add_argument("--young", required=True, help="E1,E2 (GPa)")
    parser.add_argument("--poisson", required=True, help="nu1,nu2")
    parser.add_argument("--l2-tolerance", type=float, default=0.05)
    args = parser.parse_args()

    E = [float(v) for v in args.young.split(",")]
    nu = [float(v) for v in args.poisson.split(",")]
    E_star = 1 / ((1 - nu[0] ** 2) / E[0] + (1 - nu[1] ** 2) / E[1])
    R = args.radius
    cylinder = args.geometry == "cylinder"
    axis = 1 if cylinder else 2  # the load axis: y (cylinder), z (sphere)

    # The slave facets and their thickness along z (cylinder slice).
    facets = read_slave_facets(args.mesh, args.slave_id)
    z = [x[2] for facet in facets for x in facet]
    thickness = max(z) - min(z)

    # The load from the last row of the history.
    with open(os.path.join(args.output, "time_history.csv")) as f:
        rows = list(csv.DictReader(f))
    force = float(rows[-1][args.load_column])
    if cylinder:
        load = -2 * force / thickness  # P' (kN/mm)
        b = math.sqrt(4 * load * R / (math.pi * E_star))
        p0 = 2 * load / (math.pi * b)
        area = b * thickness
        print("cylinder: R = %g mm, E* = %.6g GPa, slice t = %g mm, %s = %.6g kN"
              % (R, E_star, thickness, args.load_column, force))
        print("Johnson: P' = %.6g kN/mm, b = %.6g mm, p0 = %.6g GPa"
              % (load, b, p0))
    else:
        load = -4 * force  # P (kN)
        b = (3 * load * R / (4 * E_star)) ** (1 / 3)
        p0 = 3 * load / (2 * math.pi * b * b)
        area = math.pi * b * b / 4
        print("sphere: R = %g mm, E* = %.6g GPa, %s = %.6g kN"
              % (R, E_star, args.load_column, force))
        print("Johnson: P = %.6g kN, a = %.6g mm, p0 = %.6g GPa"
              % (load, b, p0))
    if not load > 0:
        print("FAILED: the indenter carries no compressive load")
        return 1

    # The nodal values at the slave nodes.
    time, pieces = last_field_output(args.output)
    points, data = [], {"contact_pressure": [], "displacement": []}
    for piece in pieces:
        p, d = read_vtu(piece)
        points += p
        for name in data:
            data[name] += d[name]
    locator = PointLocator(points)

    def radius(x):
        if cylinder:
            return abs(x[0])
        return math.hypot(x[0], x[1])

    nodes = {}  # reference position -> (current position, pressure)
    facet_values = []
    for facet in facets:
        values = []
        for X in facet:
            i = locator.find(X)
            if i is None:
                print("FAILED: slave node %s not in the field output" % (X,))
                return 1
            u = data["displacement"][i]
            x = tuple(X[d] + u[d] for d in range(3))
            values.append((x, data["contact_pressure"][i]))
            nodes[X] = values[-1]
        facet_values.append(values)

    # The profile up to 1.25 b: one row per position r (the cylinder's two
    # nodes across the slice, and the sphere's nodes mirrored about x = y,
    # have the same r and pressure).
    profile = {}
    for x, p in nodes.values():
        profile.setdefault(round(radius(x), 6), []).append(p)
    print("field output at t = %g: %d slave nodes" % (time, len(nodes)))
    print("%10s %12s %12s %10s" % ("r (mm)", "p_h (GPa)", "p (GPa)", "p_h - p"))
    for r in sorted(profile):
        p_h = sum(profile[r]) / len(profile[r])
        p = p0 * math.sqrt(1 - (r / b) ** 2) if r < b else 0.
        if r <= 1.25 * b:
            print("%10.5f %12.6g %12.6g %+10.2e" % (r, p_h, p, p_h - p))

    # The half-width from the nodes: between the farthest node with a
    # pressure and the nearest without; the element size: the largest
    # projected facet edge within r <= b.
    active = [radius(x) for x, p in nodes.values() if p > 0]
    inactive = [radius(x) for x, p in nodes.values() if not p > 0]
    if not active or not inactive:
        print("FAILED: %s slave node has a pressure"
              % ("no" if not active else "every"))
        return 1
    b_in, b_out = max(active), min(inactive)
    b_h = (b_in + b_out) / 2
    h = 0.
    for values in facet_values:
        if all(radius(x) <= b for x, _ in values):
            for i in range(4):
                x, y = values[i][0], values[(i + 1) % 4][0]
                edge = [x[d] - y[d] for d in range(3) if d != axis]
                if cylinder:
                    edge = edge[:1]  # along x; the slice's thickness is not a size
                h = max(h, math.hypot(*edge))

    # The L2 error over the slave surface, projected onto the contact plane.
    plane = [d for d in range(3) if d != axis]
    error2 = 0.
    gauss = gauss_points(6)
    for values in facet_values:
        xs = [v[0] for v in values]
        ps = [v[1] for v in values]
        for s, ws in gauss:
            for t, wt in gauss:
                N = [(1 - s) * (1 - t), s * (1 - t), s * t, (1 - s) * t]
                dNs = [-(1 - t), 1 - t, t, -t]
                dNt = [-(1 - s), -s, s, 1 - s]
                x = [sum(N[k] * xs[k][d] for k in range(4)) for d in range(3)]
                j = [[sum(dN[k] * xs[k][d] for k in range(4)) for dN in (dNs, dNt)]
                     for d in plane]
                jacobian = abs(j[0][0] * j[1][1] - j[0][1] * j[1][0])
                p_h = sum(N[k] * ps[k] for k in range(4))
                r = radius(x)
                p = p0 * math.sqrt(1 - (r / b) ** 2) if r < b else 0.
                error2 += ws * wt * jacobian * (p_h - p) ** 2
    l2 = math.sqrt(error2 / area) / p0

    peak = max(p for _, p in nodes.values())
    print("peak nodal pressure %.6g GPa, p0 %.6g GPa: %+.2f %% (information)"
          % (peak, p0, 100 * (peak / p0 - 1)))
    print("half-width: farthest node with a pressure at r = %.5f mm, nearest"
          " without at %.5f mm" % (b_in, b_out))
    print("half-width %.5f mm, Johnson %.5f mm: %+.5f mm, slave element %.5f mm"
          " (bound)" % (b_h, b, b_h - b, h))
    print("L2 error of the profile: %.4f %% of p0 sqrt(A_c) (bound %.4g %%)"
          % (100 * l2, 100 * args.l2_tolerance))
    failed = False
    if abs(b_h - b) > h:
        print("FAILED: the half-width is off by more than one element")
        failed = True
    if not l2 <= args.l2_tolerance:
        print("FAILED: the L2 error of the profile is above the bound")
        failed = True
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
