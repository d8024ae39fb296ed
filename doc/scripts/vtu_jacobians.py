#!/usr/bin/env python3
"""Smallest Jacobian determinants of the hexahedra in a rubberdyn ParaView
series, frame by frame (standard library only, no VTK needed):

    doc/scripts/vtu_jacobians.py OUTPUT_DIR [FIRST [LAST]]

For every frame of OUTPUT_DIR/solution.pvd (all ranks' pieces), the cells
with the smallest J = det(F) at their 2x2x2 Gauss points are listed with J at
their centre (what the F-bar element uses for the volume change) and their
reference centre, from the displacement field and the reference points of
the .vtu files (deal.II's zlib-compressed, base64-encoded binary format).
The cell-data field "J" of the output is the mean over the Gauss points; a
Gauss-point J far below the centre J is an hourglass-type distortion that the
F-bar element's volumetric term does not see.
"""
import base64
import glob
import re
import struct
import sys
import zlib

REFERENCE = [(-1, -1, -1), (1, -1, -1), (1, 1, -1), (-1, 1, -1),
             (-1, -1, 1), (1, -1, 1), (1, 1, 1), (-1, 1, 1)]  # VTK hexahedron
G = 3 ** -0.5
GAUSS = [(a * G, b * G, c * G) for a in (-1, 1) for b in (-1, 1) for c in (-1, 1)]


def read_vtu(name):
    """The binary DataArrays of one .vtu file: points, connectivity and the
    named fields, as lists of tuples (vectors) or numbers."""
    text = open(name).read()
    arrays = {}
    pattern = (r'<DataArray type="(\w+)"(?: Name="(\w+)")? ?'
               r'(?:NumberOfComponents="(\d)")? format="binary">\s*([^<]*)<')
    for m in re.finditer(pattern, text):
        kind, field = m.group(1), m.group(2) or 'points'
        components, data = int(m.group(3) or 1), m.group(4).strip()
        # Header: 4 uint32 (blocks, block size, last block size, compressed
        # size) = 24 base64 characters, then the compressed data (one block).
        n_blocks = struct.unpack('<I', base64.b64decode(data[:24])[:4])[0]
        assert n_blocks == 1, 'only single-block arrays are supported'
        raw = zlib.decompress(base64.b64decode(data[24:]))
        code = {'Float32': 'f', 'Float64': 'd', 'Int32': 'i', 'UInt8': 'B'}[kind]
        n = len(raw) // struct.calcsize(code)
        values = struct.unpack('<%d%s' % (n, code), raw)
        arrays[field] = ([values[i:i + components] for i in range(0, n, components)]
                         if components > 1 else list(values))
    return arrays


def det_dx_dxi(x, xi):
    """det(dx/dxi) of the trilinear map through the eight points x at xi."""
    m = [[0.] * 3 for _ in range(3)]
    for a, s in enumerate(REFERENCE):
        dn = (s[0] * (1 + s[1] * xi[1]) * (1 + s[2] * xi[2]) / 8,
              s[1] * (1 + s[0] * xi[0]) * (1 + s[2] * xi[2]) / 8,
              s[2] * (1 + s[0] * xi[0]) * (1 + s[1] * xi[1]) / 8)
        for i in range(3):
            for j in range(3):
                m[i][j] += x[a][i] * dn[j]
    return (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]))


def main():
    directory = sys.argv[1]
    pvd = open(directory + '/solution.pvd').read()
    frames = [(float(t), f) for t, f in
              re.findall(r'timestep="([^"]*)"[^>]*file="([^"]*)"', pvd)]
    first = int(sys.argv[2]) if len(sys.argv) > 2 else 0
    last = int(sys.argv[3]) if len(sys.argv) > 3 else len(frames) - 1
    print('time_ms,min_gauss_point_J,centre_J,reference_x,reference_y,reference_z')
    for time, pvtu in frames[first:last + 1]:
        cells = []
        for piece in sorted(glob.glob(directory + '/' + pvtu.replace('.pvtu', '.*.vtu'))):
            d = read_vtu(piece)
            points, u, connectivity = d['points'], d['displacement'], d['connectivity']
            for c in range(len(connectivity) // 8):
                nodes = connectivity[8 * c:8 * c + 8]
                X = [points[i] for i in nodes]
                x = [tuple(points[i][k] + u[i][k] for k in range(3)) for i in nodes]
                j_gauss = min(det_dx_dxi(x, q) / det_dx_dxi(X, q) for q in GAUSS)
                j_centre = det_dx_dxi(x, (0, 0, 0)) / det_dx_dxi(X, (0, 0, 0))
                centre = [sum(p[k] for p in X) / 8 for k in range(3)]
                cells.append((j_gauss, j_centre, centre))
        j_gauss, j_centre, centre = min(cells)
        print('%.4f,%.4f,%.4f,%.2f,%.2f,%.2f' % (time, j_gauss, j_centre, *centre))


if __name__ == '__main__':
    main()
