#!/usr/bin/env python3
"""Convert a Haines SPD scene (NFF) to MicroTrace's .mts, for what tree3.nff and lattice1.nff use.

    python3 scripts/nff2mts.py ../shared/spd/tree3.nff > scenes/spd/tree3.mts

The .mts camera always looks along -z from its eye onto a view plane z = D, so the whole scene
is moved into the NFF camera's frame: eye at the origin, looking along -z, view plane z = -1,
the window the field of view. Supported: `v` (from, at, up, angle, resolution; hither is
ignored), `b`, `l` (only the first light: the format keeps one), `f`, `s`, `c` and `p` with four
vertices forming a rectangle. Approximations (written into the scene's header):
- a cone with two radii (a truncated cone, which .mts lacks) becomes a cylinder of the mean
  radius; .mts cylinders are capped, NFF ones are not;
- a rectangle becomes a cube 0.01 thick below its plane (on the side opposite its normal).
"""
import math
import sys

THICKNESS = 0.01


def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def dot(a, b):
    return sum(a[i] * b[i] for i in range(3))


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def unit(a):
    length = math.sqrt(dot(a, a))
    return [c / length for c in a]


def fmt(x):
    text = f"{x:.9g}"
    return "0" if text == "-0" else text


def rotation_statements(columns):
    """`rotate x a`, `rotate y b`, `rotate z c` for the rotation whose columns are `columns`
    (R = Rz(c) Ry(b) Rx(a) acting on column vectors: the order .mts applies them)."""
    r = [[columns[j][i] for j in range(3)] for i in range(3)]  # r[row][column]
    b = math.asin(max(-1.0, min(1.0, -r[2][0])))
    if abs(r[2][0]) < 1 - 1e-12:
        a = math.atan2(r[2][1], r[2][2])
        c = math.atan2(r[1][0], r[0][0])
    else:  # gimbal lock: put everything in a
        a = math.atan2(-r[1][2], r[1][1])
        c = 0.0
    # Check by recomposing.
    def rx(t):
        return [[1, 0, 0], [0, math.cos(t), -math.sin(t)], [0, math.sin(t), math.cos(t)]]

    def ry(t):
        return [[math.cos(t), 0, math.sin(t)], [0, 1, 0], [-math.sin(t), 0, math.cos(t)]]

    def rz(t):
        return [[math.cos(t), -math.sin(t), 0], [math.sin(t), math.cos(t), 0], [0, 0, 1]]

    def mul(p, q):
        return [[sum(p[i][k] * q[k][j] for k in range(3)) for j in range(3)] for i in range(3)]

    back = mul(rz(c), mul(ry(b), rx(a)))
    assert all(abs(back[i][j] - r[i][j]) < 1e-9 for i in range(3) for j in range(3)), (r, back)
    out = []
    for axis, angle in (("x", a), ("y", b), ("z", c)):
        degrees = math.degrees(angle)
        if abs(degrees) > 1e-9:
            out.append(f"  rotate {axis} {fmt(degrees)}")
    return out


def frame_about(d):
    """An orthonormal right-handed frame (e1, e2, d) with d unit."""
    helper = [1.0, 0.0, 0.0] if abs(d[0]) < 0.6 else [0.0, 1.0, 0.0]
    e1 = unit(cross(helper, d))
    e2 = cross(d, e1)
    return [e1, e2, d]


def main(path):
    tokens_by_line = [line.split() for line in open(path) if line.strip() and not line.startswith("#")]
    view = {}
    background = None
    lights = []
    material = None
    objects = []  # (kind, material, data)
    i = 0
    while i < len(tokens_by_line):
        t = tokens_by_line[i]
        key = t[0]
        if key == "v":
            for j in range(1, 7):
                view[tokens_by_line[i + j][0]] = [float(x) for x in tokens_by_line[i + j][1:]]
            i += 7
            continue
        if key == "b":
            background = [float(x) for x in t[1:4]]
        elif key == "l":
            lights.append([float(x) for x in t[1:4]])
        elif key == "f":
            material = [float(x) for x in t[1:]]
        elif key == "s":
            objects.append(("sphere", material, [float(x) for x in t[1:5]]))
        elif key == "c":
            objects.append(("cone", material, [float(x) for x in t[1:9]]))
        elif key == "p":
            count = int(t[1])
            vertices = [[float(x) for x in tokens_by_line[i + 1 + k]] for k in range(count)]
            objects.append(("polygon", material, vertices))
            i += 1 + count
            continue
        else:
            sys.exit(f"{path}: unsupported NFF statement {key!r}")
        i += 1

    eye, at, up = view["from"], view["at"], view["up"]
    forward = unit(sub(at, eye))
    right = unit(cross(forward, up))
    true_up = cross(right, forward)
    # Camera frame: x = right, y = up, z = -forward; p_cam = R (p - eye).
    rows = [right, true_up, [-c for c in forward]]

    def to_camera_vector(v):
        return [dot(rows[k], v) for k in range(3)]

    def to_camera(p):
        return to_camera_vector(sub(p, eye))

    half = math.tan(math.radians(view["angle"][0]) / 2)
    width, height = (int(view["resolution"][0]), int(view["resolution"][1]))
    name = path.rsplit("/", 1)[-1]

    # Colour groups: one per distinct material colour (4-bit cells), the background last.
    groups = {}

    def group_of(rgb):
        cell = tuple(max(0, min(15, round(15 * c))) for c in rgb)
        if cell not in groups:
            groups[cell] = len(groups) + 1
        return groups[cell]

    out = [
        f"# {name[:-4]}.mts -- Eric Haines' SPD scene {name}, converted by scripts/nff2mts.py.",
        "# The scene is moved into the NFF camera's frame (eye at the origin looking along -z).",
        "# Approximations: truncated cones become cylinders of the mean radius, the ground",
        f"# rectangle a cube {THICKNESS} thick; only the first of {len(lights)} lights (the format keeps one).",
        "",
        f"viewport 0 {width - 1} 0 {height - 1}",
        f"window {fmt(-half)} {fmt(half)} {fmt(-half)} {fmt(half)}",
        "viewplane -1",
        "perspective 0 0 0",
        "light point " + " ".join(fmt(c) for c in to_camera(lights[0])),
        "ambient 0.1",
        "shadows on",
        "dither off",
    ]
    body = []
    for kind, m, data in objects:
        colour = group_of(m[0:3])
        kd, ks, shine = m[3], m[4], m[5]
        if kind == "sphere":
            centre, radius = to_camera(data[0:3]), data[3]
            body += ["sphere", f"  scale {fmt(radius)} {fmt(radius)} {fmt(radius)}"]
            translate = centre
        elif kind == "cone":
            base, r0, apex, r1 = data[0:3], data[3], data[4:7], data[7]
            axis = to_camera_vector(sub(apex, base))
            length = math.sqrt(dot(axis, axis))
            radius = (r0 + r1) / 2
            body += ["cylinder", f"  scale {fmt(radius)} {fmt(radius)} {fmt(length)}"]
            body += rotation_statements(frame_about(unit(axis)))
            translate = to_camera(base)
        else:
            if len(data) != 4:
                sys.exit(f"{path}: only four-vertex polygons are supported")
            v0, v1, _, v3 = data
            e1, e2 = sub(v1, v0), sub(v3, v0)
            if abs(dot(e1, e2)) > 1e-9 * math.sqrt(dot(e1, e1) * dot(e2, e2)):
                sys.exit(f"{path}: only rectangular polygons are supported")
            normal = unit(cross(e1, e2))
            columns = [to_camera_vector(unit(e1)), to_camera_vector(unit(e2)), to_camera_vector(normal)]
            body += ["cube", f"  scale {fmt(math.sqrt(dot(e1, e1)))} {fmt(math.sqrt(dot(e2, e2)))} {fmt(THICKNESS)}"]
            body += rotation_statements(columns)
            translate = to_camera([v0[k] - THICKNESS * normal[k] for k in range(3)])
        body += [
            "  translate " + " ".join(fmt(c) for c in translate),
            f"  colour {colour}",
            f"  kd {fmt(kd)}",
            f"  ks {fmt(ks)}",
            f"  pwr {fmt(min(shine, 1e6))}",
            "  cmy " + " ".join(fmt(1 - c) for c in m[0:3]),
        ]
    background_group = group_of(background)
    shade = max(0, min(15, round(15 * max(background))))
    for cell, number in sorted(groups.items(), key=lambda item: item[1]):
        out.append(f"group {number} {cell[0]} {cell[1]} {cell[2]} up")
    out.append(f"background {16 * background_group + shade}")
    out.append("")
    print("\n".join(out + body))


if __name__ == "__main__":
    main(sys.argv[1])
