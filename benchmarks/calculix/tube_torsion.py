#!/usr/bin/env python3
"""The bonded tube in azimuthal shear (doc/verification/reference_solutions.md section 3) in
CalculiX, on rubberdyn's own mesh: writes the deck, runs nothing.

  tube_torsion.py MESH.msh ELEMENT OUT.inp      write the deck
  tube_torsion.py --torque MESH.msh JOB.dat     the torque per step (CSV)

The deck: the hexahedra of MESH.msh (Gmsh 2.2 ASCII; Gmsh's hexahedron
numbering is Abaqus's: the bottom face, then the top) as ELEMENT (C3D8,
C3D8I, C3D8R), the reference study's Yeoh rubber at K/G = 1250 (*HYPERELASTIC,
YEOH; units N, mm, MPa: C10 = 0.55, C20 = -0.05, C30 = 0.015 MPa,
D1 = 2 / K), the inner surface held in x and y, each end held in z, and the
outer surface turned about the axis by phi_k = 1.039247 k / 10 rad in ten
*STEPs with NLGEOM. Each step moves the prescribed displacements linearly
from phi_{k-1} to phi_k (a chord, not the arc), but the material is
hyperelastic, so every step's end state is the equilibrium at phi_k, the
same as rubberdyn's load path. The torque is the moment about the z axis of
the reaction forces on the outer nodes at their current positions,
sum (x + u_x) RF_y - (y + u_y) RF_x, from *NODE PRINT of U and RF.
"""
import math
import sys

PHI = 1.039247
STEPS = 10


def read_msh(path):
    nodes, hexes, faces = {}, [], {}
    with open(path) as f:
        lines = iter(f.read().split('\n'))
    for line in lines:
        if line == '$Nodes':
            for _ in range(int(next(lines))):
                w = next(lines).split()
                nodes[int(w[0])] = tuple(float(x) for x in w[1:4])
        elif line == '$Elements':
            for _ in range(int(next(lines))):
                w = [int(x) for x in next(lines).split()]
                kind, n_tags = w[1], w[2]
                tag, vertices = w[3], w[3 + n_tags:]
                if kind == 5:
                    hexes.append(vertices)
                elif kind == 3:
                    faces.setdefault(tag, set()).update(vertices)
    return nodes, hexes, faces


def node_set(name, ids):
    ids = sorted(ids)
    rows = [', '.join(str(i) for i in ids[k:k + 12]) for k in range(0, len(ids), 12)]
    return '*NSET, NSET=%s\n%s\n' % (name, '\n'.join(rows))


def write_deck(mesh, element, out):
    nodes, hexes, faces = read_msh(mesh)
    G, nu = 1.1, 0.4996                     # MPa
    K = 2 * G * (1 + nu) / (3 * (1 - 2 * nu))
    with open(out, 'w') as f:
        f.write('** rubberdyn benchmarks/calculix/tube_torsion.py from %s\n' % mesh)
        f.write('*NODE, NSET=ALL\n')
        for i, x in sorted(nodes.items()):
            f.write('%d, %.15g, %.15g, %.15g\n' % (i, *x))
        f.write('*ELEMENT, TYPE=%s, ELSET=RUBBER\n' % element)
        for e, v in enumerate(hexes, 1):
            f.write('%d, %s\n' % (e, ', '.join(str(i) for i in v)))
        for tag, name in ((1, 'INNER'), (2, 'OUTER'), (3, 'END_BOTTOM'), (4, 'END_TOP')):
            f.write(node_set(name, faces[tag]))
        f.write('*MATERIAL, NAME=RUBBER\n*HYPERELASTIC, YEOH\n')
        f.write('0.55, -0.05, 0.015, %.15g, 1e30, 1e30\n' % (2 / K))
        f.write('*SOLID SECTION, ELSET=RUBBER, MATERIAL=RUBBER\n')
        f.write('*BOUNDARY\nINNER, 1, 2\nEND_BOTTOM, 3, 3\nEND_TOP, 3, 3\n')
        outer = sorted(faces[2])
        for k in range(1, STEPS + 1):
            phi = PHI * k / STEPS
            f.write('*STEP, NLGEOM, INC=1000\n*STATIC\n0.1, 1., 1e-5, 0.25\n')
            f.write('*BOUNDARY\n')
            for i in outer:
                x, y, _ = nodes[i]
                f.write('%d, 1, 1, %.15g\n' % (i, x * (math.cos(phi) - 1) - y * math.sin(phi)))
                f.write('%d, 2, 2, %.15g\n' % (i, x * math.sin(phi) + y * (math.cos(phi) - 1)))
            f.write('*NODE PRINT, NSET=OUTER, TOTALS=NO\nU, RF\n*END STEP\n')


def torque(mesh, dat):
    """The torque (kN mm) at the end of every step: the .dat file lists, at
    every increment, 'displacements (vx,vy,vz) for set OUTER and time T'
    then 'forces (fx,fy,fz) for set OUTER and time T', one node per line;
    step k ends at the total time T = k."""
    nodes, _, _ = read_msh(mesh)
    u, rf, current = {}, {}, None
    with open(dat) as f:
        for line in f:
            w = line.split()
            if line.strip().startswith(('displacements', 'forces')):
                time = float(w[-1])
                current = (u if w[0] == 'displacements' else rf).setdefault(time, {})
            elif current is not None and len(w) == 4:
                try:
                    current[int(w[0])] = tuple(float(x) for x in w[1:])
                except ValueError:
                    pass
    print('phi,torque')
    for k in range(1, STEPS + 1):
        if float(k) not in rf:
            break
        m = 0.
        for i, f in rf[float(k)].items():
            x, y, _ = nodes[i]
            d = u[float(k)][i]
            m += (x + d[0]) * f[1] - (y + d[1]) * f[0]
        # N mm -> kN mm
        print('%.6f,%.9g' % (PHI * k / STEPS, m * 1e-3))


if __name__ == '__main__':
    if sys.argv[1] == '--torque':
        torque(sys.argv[2], sys.argv[3])
    else:
        write_deck(*sys.argv[1:4])
