#!/usr/bin/env python3
"""Write a structured, layered box as a Gmsh 2.2 ASCII mesh of quadrilaterals
(2-D) or hexahedra (3-D), with named physical groups: one volume (surface in
2-D) group per layer and one boundary group per side.

    contrib/make-box-mesh.py --dim 2 --size 1000 1000 --cells 4 4 \
        --layers 500 -o meshes/two_layer_box_2d.msh

Layers are cut at the given heights (last coordinate); the top layer is
named 'layer0', the next 'layer1', and so on. Sides are named west/east
(x), south/north (y, 3-D) and bottom/top.

--profile X0:DZ0 X1:DZ1 ... makes the (single) layer interface non-planar:
it is moved up by DZ, linearly interpolated in x between the given points
(constant outside them), and the grid lines above and below it are
stretched to follow, so the interface stays a surface of mesh faces. For
example, a fault with a kink:

    contrib/make-box-mesh.py --dim 2 --size 1000 1000 --cells 8 8 \
        --layers 500 --profile 0:-50 500:50 1000:-250 -o kinked.msh
"""
import argparse
import sys


def main():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--dim", type=int, choices=(2, 3), default=2)
    p.add_argument("--size", type=float, nargs="+", required=True)
    p.add_argument("--cells", type=int, nargs="+", required=True)
    p.add_argument("--layers", type=float, nargs="*", default=[])
    p.add_argument("--profile", nargs="*", default=[],
                   help="X:DZ points of a piecewise linear offset of the "
                   "layer interface (one layer only)")
    p.add_argument("-o", "--output", required=True)
    a = p.parse_args()
    dim = a.dim
    if len(a.size) != dim or len(a.cells) != dim:
        p.error("--size and --cells need %d values each" % dim)
    profile = sorted(tuple(map(float, s.split(":"))) for s in a.profile)
    if profile and len(a.layers) != 1:
        p.error("--profile needs exactly one value in --layers")

    n = a.cells
    coords = [[a.size[d] * i / n[d] for i in range(n[d] + 1)] for d in range(dim)]
    # Move the vertical grid lines nearest to each layer height onto it.
    for h in a.layers:
        z = coords[dim - 1]
        k = min(range(1, len(z) - 1), key=lambda i: abs(z[i] - h))
        z[k] = h
    n_layers = len(a.layers) + 1
    heights = sorted(a.layers, reverse=True)

    def offset(x):
        if not profile:
            return 0.0
        if x <= profile[0][0]:
            return profile[0][1]
        for (x0, d0), (x1, d1) in zip(profile, profile[1:]):
            if x <= x1:
                return d0 + (d1 - d0) * (x - x0) / (x1 - x0)
        return profile[-1][1]

    def height(x, z):
        """The vertical coordinate of a node at x whose flat height is z:
        stretched so that the interface moves by offset(x)."""
        if not profile:
            return z
        h, top, d = a.layers[0], a.size[dim - 1], offset(x)
        if not 0 < h + d < top:
            sys.exit("--profile moves the interface out of the box at x = %g" % x)
        return z * (h + d) / h if z <= h else h + d + (z - h) * (top - h - d) / (top - h)

    def node_id(idx):
        i = 0
        stride = 1
        for d in range(dim):
            i += idx[d] * stride
            stride *= n[d] + 1
        return i + 1

    nodes = []
    if dim == 2:
        for j in range(n[1] + 1):
            for i in range(n[0] + 1):
                nodes.append((node_id((i, j)), coords[0][i],
                              height(coords[0][i], coords[1][j]), 0.0))
    else:
        for k in range(n[2] + 1):
            for j in range(n[1] + 1):
                for i in range(n[0] + 1):
                    nodes.append((node_id((i, j, k)), coords[0][i], coords[1][j],
                                  height(coords[0][i], coords[2][k])))

    side_names = ["west", "east", "bottom", "top"] if dim == 2 else \
        ["west", "east", "south", "north", "bottom", "top"]
    # Physical tags: boundaries 1.., layers after them.
    side_tag = {name: i + 1 for i, name in enumerate(side_names)}
    layer_tag = [len(side_names) + 1 + l for l in range(n_layers)]

    elements = []
    if dim == 2:
        for j in range(n[1]):
            for i in range(n[0]):
                zc = 0.5 * (coords[1][j] + coords[1][j + 1])
                layer = sum(1 for h in heights if zc < h)
                elements.append((3, layer_tag[layer],
                                 [node_id((i, j)), node_id((i + 1, j)),
                                  node_id((i + 1, j + 1)), node_id((i, j + 1))]))
        for j in range(n[1]):
            elements.append((1, side_tag["west"], [node_id((0, j)), node_id((0, j + 1))]))
            elements.append((1, side_tag["east"], [node_id((n[0], j)), node_id((n[0], j + 1))]))
        for i in range(n[0]):
            elements.append((1, side_tag["bottom"], [node_id((i, 0)), node_id((i + 1, 0))]))
            elements.append((1, side_tag["top"], [node_id((i, n[1])), node_id((i + 1, n[1]))]))
    else:
        for k in range(n[2]):
            for j in range(n[1]):
                for i in range(n[0]):
                    zc = 0.5 * (coords[2][k] + coords[2][k + 1])
                    layer = sum(1 for h in heights if zc < h)
                    v = [node_id((i, j, k)), node_id((i + 1, j, k)),
                         node_id((i + 1, j + 1, k)), node_id((i, j + 1, k)),
                         node_id((i, j, k + 1)), node_id((i + 1, j, k + 1)),
                         node_id((i + 1, j + 1, k + 1)), node_id((i, j + 1, k + 1))]
                    elements.append((5, layer_tag[layer], v))

        def quad(d, side, a_, b_):
            idx = [0, 0, 0]
            out = []
            dirs = [e for e in range(3) if e != d]
            for (s, t) in ((0, 0), (1, 0), (1, 1), (0, 1)):
                idx[d] = side
                idx[dirs[0]] = a_ + s
                idx[dirs[1]] = b_ + t
                out.append(node_id(tuple(idx)))
            return out

        for d, (lo, hi) in enumerate((("west", "east"), ("south", "north"), ("bottom", "top"))):
            dirs = [e for e in range(3) if e != d]
            for a_ in range(n[dirs[0]]):
                for b_ in range(n[dirs[1]]):
                    elements.append((3, side_tag[lo], quad(d, 0, a_, b_)))
                    elements.append((3, side_tag[hi], quad(d, n[d], a_, b_)))

    with open(a.output, "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n")
        f.write("$PhysicalNames\n%d\n" % (len(side_names) + n_layers))
        for name in side_names:
            f.write('%d %d "%s"\n' % (dim - 1, side_tag[name], name))
        for l in range(n_layers):
            f.write('%d %d "layer%d"\n' % (dim, layer_tag[l], l))
        f.write("$EndPhysicalNames\n$Nodes\n%d\n" % len(nodes))
        for (i, x, y, z) in nodes:
            f.write("%d %.10g %.10g %.10g\n" % (i, x, y, z))
        f.write("$EndNodes\n$Elements\n%d\n" % len(elements))
        for e, (etype, tag, v) in enumerate(elements):
            f.write("%d %d 2 %d %d %s\n" % (e + 1, etype, tag, tag, " ".join(map(str, v))))
        f.write("$EndElements\n")


if __name__ == "__main__":
    main()
