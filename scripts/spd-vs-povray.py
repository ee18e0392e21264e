#!/usr/bin/env python3
"""Haines' SPD scenes rendered by MicroTrace and by POV-Ray 3.7, side by side (issue 24).

    python3 scripts/spd-vs-povray.py [--size 512] [--rounds 3] [--scenes balls,tree] [--out docs/spd-povray.md]

Each scene of scenes/spd/full/ is converted from NFF to POV-Ray's language as MicroTrace reads
it (docs/nff.md): the same camera (NFF's angle spans the first to the last pixel centre), every
light at 1/sqrt(n), Kd, Ks as highlight and mirror, Shine, T and the index of refraction, open
cones, polygons (even-odd, as POV-Ray's polygon is), patches as smooth triangles, ray depth 5,
no antialiasing. Then both programs render it at the SPD's 512x512 on one thread (POV-Ray's
+WT1, MicroTrace's --threads 1), alternately, `--rounds` times each; the report gives each
program's median wall time for the whole process (reading the scene included) and the ratio.
Needs `povray` (Debian's package) and a release build of `microtrace`
(cargo build --release); writes its work files under target/spd-povray/.
"""
import argparse
import gzip
import math
import os
import re
import json
import statistics
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENES = ["balls", "gears", "mount", "rings", "teapot", "tetra", "tree"]


def tokens(text):
    for line in text.splitlines():
        line = line.split("#", 1)[0]
        for word in line.split():
            yield word


def vec(values):
    return "<%s>" % ", ".join("%.9g" % v for v in values)


def convert(text, size):
    """NFF text -> POV-Ray scene text, as MicroTrace maps NFF (docs/nff.md)."""
    words = tokens(text)
    out = []
    lights = []
    view = {}
    background = (0.0, 0.0, 0.0)
    material = None

    def number():
        return float(next(words))

    def point():
        return (number(), number(), number())

    for word in words:
        if word == "v":
            continue
        if word in ("from", "at", "up"):
            view[word] = point()
        elif word in ("angle", "hither", "yon"):
            view[word] = number()
        elif word == "resolution":
            view[word] = (number(), number())
        elif word == "b":
            background = point()
        elif word == "l":
            position = point()
            # An optional colour: MicroTrace weighs the light by its luminance.
            lights.append(position)
        elif word == "f":
            r, g, b = point()
            kd, ks, shine, t, ior = number(), number(), number(), number(), number()
            if t <= 0 and ior == 0:
                ior = 1.0
            finish = "diffuse %.9g specular %.9g roughness %.9g reflection %.9g ambient 0.1" % (
                kd, ks, 1.0 / max(min(shine, 1e6), 1.0), min(ks, 1.0))
            pigment = "color rgbt <%.9g, %.9g, %.9g, %.9g>" % (r, g, b, t)
            interior = " interior { ior %.9g }" % ior if t > 0 else ""
            material = "texture { pigment { %s } finish { %s } }%s" % (pigment, finish, interior)
        elif word == "s":
            centre, radius = point(), number()
            out.append("sphere { %s, %.9g %s }" % (vec(centre), abs(radius), material))
        elif word == "c":
            base, r0 = point(), number()
            apex, r1 = point(), number()
            out.append("cone { %s, %.9g, %s, %.9g open %s }" % (vec(base), abs(r0), vec(apex), abs(r1), material))
        elif word in ("p", "pp"):
            count = int(number())
            vertices, normals = [], []
            for _ in range(count):
                vertices.append(point())
                if word == "pp":
                    normals.append(point())
            if word == "p":
                closed = vertices + [vertices[0]]
                out.append("polygon { %d, %s %s }" % (len(closed), ", ".join(vec(v) for v in closed), material))
            else:
                for k in range(1, count - 1):
                    corners = [0, k, k + 1]
                    parts = ", ".join("%s, %s" % (vec(vertices[c]), vec(normals[c])) for c in corners)
                    out.append("smooth_triangle { %s %s }" % (parts, material))
        else:
            sys.exit("unknown NFF statement %r" % word)
    width, height = size, size
    # MicroTrace's window: the first and last pixel centres at +-tan(angle/2); POV-Ray's angle
    # spans the image's outer edges.
    half = math.tan(math.radians(view["angle"]) / 2) * width / max(width - 1, 1)
    pov_angle = math.degrees(2 * math.atan(half))
    share = 1.0 / math.sqrt(max(len(lights), 1))
    head = [
        "#version 3.7;",
        "global_settings { max_trace_level 5 assumed_gamma 1.0 ambient_light rgb <1, 1, 1> }",
        "background { color rgb %s }" % vec(background),
        # Right-handed coordinates: the right vector points the other way.
        "camera { perspective location %s look_at %s sky %s right -x*%.9g up y angle %.9g }" % (
            vec(view["from"]), vec(view["at"]), vec(view["up"]), width / height, pov_angle),
    ]
    for position in lights:
        head.append("light_source { %s color rgb <%.9g, %.9g, %.9g> }" % (vec(position), share, share, share))
    return "\n".join(head + out) + "\n"


def timed(command):
    """The wall time of the whole process, and what it wrote on stderr."""
    started = time.perf_counter()
    result = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    elapsed = time.perf_counter() - started
    if result.returncode != 0:
        sys.exit("%s failed:\n%s" % (" ".join(command), result.stderr[-2000:]))
    return elapsed, result.stderr


def pov_trace_seconds(stderr):
    """POV-Ray's own "Trace Time" (the render, without parsing and start-up)."""
    match = re.search(r"Trace Time:.*\(([\d.]+) seconds\)", stderr)
    return float(match.group(1)) if match else float("nan")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--size", type=int, default=512)
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--scenes", default=",".join(SCENES))
    parser.add_argument("--out")
    args = parser.parse_args()
    microtrace = os.path.join(ROOT, "target", "release", "microtrace")
    if not os.path.exists(microtrace):
        sys.exit("build microtrace first: cargo build --release")
    work = os.path.join(ROOT, "target", "spd-povray")
    os.makedirs(work, exist_ok=True)
    version = subprocess.run(["povray", "--version"], capture_output=True, text=True)
    pov_version = next((line for line in (version.stdout + version.stderr).splitlines() if line.startswith("POV-Ray")), "POV-Ray")
    rows = []
    for name in args.scenes.split(","):
        scene = os.path.join(ROOT, "scenes", "spd", "full", name + ".nff.gz")
        text = gzip.open(scene, "rt").read()
        pov = os.path.join(work, name + ".pov")
        with open(pov, "w") as handle:
            handle.write(convert(text, args.size))
        ours, theirs, our_trace, their_trace = [], [], [], []
        stats = os.path.join(work, name + "-stats.json")
        for _ in range(args.rounds):
            wall, _ = timed([microtrace, "render", scene, "--mode", "rgb", "--number", "f32", "--threads", "1",
                             "--size", "%dx%d" % (args.size, args.size), "--stats-json", stats, "--out", os.path.join(work, name + "-microtrace.png")])
            ours.append(wall)
            with open(stats) as handle:
                figures = json.load(handle)
            our_trace.append((figures["preprocess_ms"] + figures["trace_ms"]) / 1000.0)
            wall, stderr = timed(["povray", "-D", "-A", "+WT1", "File_Gamma=1.0", "+W%d" % args.size, "+H%d" % args.size, "+I" + pov,
                                  "+O" + os.path.join(work, name + "-povray.png")])
            theirs.append(wall)
            their_trace.append(pov_trace_seconds(stderr))
            print("%s: microtrace %.3f s (tracer %.3f s), povray %.3f s (trace %.3f s)" % (name, ours[-1], our_trace[-1], theirs[-1], their_trace[-1]), file=sys.stderr)
        rows.append((name, statistics.median(ours), statistics.median(theirs), statistics.median(our_trace), statistics.median(their_trace)))
    lines = [
        "<!-- written by `python3 scripts/spd-vs-povray.py`; do not edit by hand -->",
        "# Haines' SPD scenes: MicroTrace against POV-Ray",
        "",
        "Each scene of `scenes/spd/full/` at %dx%d, one thread each (`microtrace render --threads 1 "
        "--number f32 --mode rgb`; %s with `+WT1 -A`), the whole process timed (reading the scene "
        "included), alternately, the median of %d runs each on this machine. The POV-Ray scene is "
        "the NFF converted by the script as MicroTrace reads it (docs/nff.md)." % (args.size, args.size, pov_version, args.rounds),
        "",
        "Two ratios: of the whole processes, and of the renders alone (MicroTrace's preparation and "
        "trace as `--stats-json` gives them; POV-Ray's own *Trace Time*, without its parsing and "
        "start-up, which take it about 0.7 s on any of these scenes).",
        "",
        "| scene | MicroTrace, process | POV-Ray, process | ratio (POV-Ray / MicroTrace) | MicroTrace, preparation + trace | POV-Ray, trace | ratio |",
        "|---|---:|---:|---:|---:|---:|---:|",
    ]
    for name, ours, theirs, our_trace, their_trace in rows:
        lines.append("| %s | %.3f s | %.3f s | %.2fx | %.3f s | %.3f s | %.2fx |" % (name, ours, theirs, theirs / ours, our_trace, their_trace, their_trace / our_trace))
    report = "\n".join(lines) + "\n"
    print(report)
    if args.out:
        with open(args.out, "w") as handle:
            handle.write(report)


if __name__ == "__main__":
    main()
