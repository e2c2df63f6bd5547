#!/usr/bin/env python3
"""Writes a big binary STL for the "Big meshes" benchmark (BENCHMARKS.md): a torus tessellated
into a grid of U x V cells, two triangles each, every vertex shared by six triangles as a
scanner's or CAD exporter's mesh shares them, with each facet's true normal (as exporters write
it). 2 U V triangles, 84 + 100 U V bytes. Keep the output out of git (it is around a gigabyte).

    python3 bench/make_big_stl.py /tmp/big.stl --triangles 20000000
    python3 bench/make_big_stl.py /tmp/big_zero.stl --triangles 2000000 --zero-normals
"""
import argparse
import math
import struct
import sys


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("output")
    parser.add_argument("--triangles", type=int, default=20_000_000)
    parser.add_argument("--zero-normals", action="store_true",
                        help="write 0 0 0 normals (facet then computes smooth ones)")
    args = parser.parse_args()
    cells = max(1, args.triangles // 2)
    v_cells = max(3, int(math.sqrt(cells / 1.6)))  # the tube's cells: U about 1.6 V
    u_cells = max(3, cells // v_cells)
    big, small = 1.0, 0.4

    def ring(j):
        phi = 2 * math.pi * (j % v_cells) / v_cells
        r = big + small * math.cos(phi)
        z = small * math.sin(phi)
        out = []
        for i in range(u_cells):
            theta = 2 * math.pi * i / u_cells
            # Rounded to float now so that a shared vertex has the same bits in every facet.
            out.append(struct.unpack("<3f", struct.pack("<3f", r * math.cos(theta),
                                                         r * math.sin(theta), z)))
        return out

    record = struct.Struct("<12fH")
    zero = args.zero_normals

    def facet(a, b, c):
        if zero:
            return record.pack(0.0, 0.0, 0.0, *a, *b, *c, 0)
        ux, uy, uz = b[0] - a[0], b[1] - a[1], b[2] - a[2]
        vx, vy, vz = c[0] - a[0], c[1] - a[1], c[2] - a[2]
        nx, ny, nz = uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx
        length = math.sqrt(nx * nx + ny * ny + nz * nz) or 1.0
        return record.pack(nx / length, ny / length, nz / length, *a, *b, *c, 0)

    count = 2 * u_cells * v_cells
    with open(args.output, "wb") as out:
        out.write(b"facet big-mesh benchmark torus".ljust(80, b" "))
        out.write(struct.pack("<I", count))
        here = ring(0)
        for j in range(v_cells):
            there = ring(j + 1)
            chunk = []
            for i in range(u_cells):
                k = (i + 1) % u_cells
                # Counter-clockwise seen from outside the tube.
                chunk.append(facet(here[i], here[k], there[k]))
                chunk.append(facet(here[i], there[k], there[i]))
            out.write(b"".join(chunk))
            here = there
    print(f"{args.output}: {count} triangles, {84 + 50 * count} bytes", file=sys.stderr)


if __name__ == "__main__":
    main()
