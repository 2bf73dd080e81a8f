#!/usr/bin/env python3
"""Writes the four benchmark parts of `resharp simulate` (docs/design.md section 4):

  mech      2.5D, flat end mills only: a step, a rounded pocket, a round pocket
            cut with arcs, a slot and drilled holes (Type 1 edges only)
  frogface  a ball-end free-form cavity under the flat top face (Type 2 edges)
  cavity    a drafted cavity whose floor, walls and top are all ball-end
            finished, so every face is scalloped (Type 3 edges)
  impeller  blades left standing between ball-end scalloped channels (3-axis)
  vcarve    V-grooves cut by V-bits (straight, at several depths, along arcs and one
            ramping so its width grows) and 45-degree chamfers cut by a chamfer mill
            along the stock's top edges and a round pocket's rim: slanted flanks
            that are real faces

Each part gets examples/<part>/<part>.nc and examples/<part>/job.json. Run from
anywhere: python3 examples/make_programs.py. Only the standard library is used and
the output is deterministic, so the committed files can be regenerated and diffed.
"""

import json
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
SAFE_Z = 45.0  # clearance plane above every stock, mm


class Program:
    """Collects G-code blocks; coordinates are written with 4 decimals."""

    def __init__(self, title):
        self.lines = ["%", f"({title})", "G90 G21 G17 G40 G49 G80 G94"]
        self.mode = None

    @staticmethod
    def num(value):
        text = f"{value:.4f}".rstrip("0").rstrip(".")
        return "0" if text in ("-0", "") else text

    def emit(self, mode, **words):
        body = " ".join(f"{k}{self.num(v)}" for k, v in words.items())
        prefix = "" if mode == self.mode else mode + " "
        self.mode = mode
        self.lines.append(prefix + body)

    def tool(self, number, comment):
        self.lines.append(f"T{number} M6 ({comment})")
        self.lines.append("S12000 M3")
        self.mode = None

    def rapid(self, **words):
        self.emit("G0", **words)

    def feed(self, **words):
        self.emit("G1", **words)

    def arc(self, clockwise, x, y, i, j, z=None):
        words = {"X": x, "Y": y}
        if z is not None:
            words["Z"] = z
        words.update({"I": i, "J": j})
        self.emit("G2" if clockwise else "G3", **words)

    def retract(self):
        self.rapid(Z=SAFE_Z)

    def polyline(self, points):
        """Rapid above the first point, plunge, then cut through all points."""
        x, y, z = points[0]
        self.retract()
        self.rapid(X=x, Y=y)
        self.feed(Z=z, F=600)
        for x, y, z in points[1:]:
            self.feed(X=x, Y=y, Z=z)

    def finish(self):
        self.retract()
        self.lines += ["M5", "M30", "%"]
        return "\n".join(self.lines) + "\n"


def write_part(name, stock_min, stock_max, tools, program):
    folder = os.path.join(HERE, name)
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, f"{name}.nc"), "w") as f:
        f.write(program)
    job = {
        "stock": {"min": stock_min, "max": stock_max},
        "pitch": 0.5,
        "program": f"{name}.nc",
        "start": [stock_min[0], stock_min[1], SAFE_Z + 20],
        "tools": tools,
    }
    with open(os.path.join(folder, "job.json"), "w") as f:
        json.dump(job, f, indent=2)
        f.write("\n")


def zigzag(p, x0, x1, y0, y1, z, step):
    """Parallel passes along x over [x0, x1] x [y0, y1] at height z."""
    y, forward = y0, True
    p.retract()
    p.rapid(X=x0, Y=y0)
    p.feed(Z=z, F=800)
    while True:
        p.feed(X=x1 if forward else x0, Y=y)
        if y >= y1:
            break
        y = min(y + step, y1)
        forward = not forward
        p.feed(Y=y)
    p.retract()


def mech():
    p = Program("mech: 2.5D flat-end part")
    p.tool(1, "flat end mill D10")
    # A step along the -x side: 10 mm down over x < 22.
    for z in (25.0, 20.0):
        zigzag(p, -6.0, 17.0, -6.0, 96.0, z, 8.0)
    # A rounded rectangular pocket [32, 78] x [14, 52], 11 mm deep, in two levels.
    for z in (24.5, 19.0):
        zigzag(p, 37.0, 73.0, 19.0, 47.0, z, 7.0)
        p.rapid(X=37.0, Y=19.0)
        p.feed(Z=z)
        for x, y in ((73.0, 19.0), (73.0, 47.0), (37.0, 47.0), (37.0, 19.0)):
            p.feed(X=x, Y=y)
        p.retract()
    # A round pocket of radius 16 around (100, 66), 12 mm deep, cut ring by ring with arcs.
    cx, cy = 100.0, 66.0
    for z in (24.0, 18.0):
        p.rapid(X=cx, Y=cy)
        p.feed(Z=z)
        for ring in (3.0, 7.0, 11.0):
            p.feed(X=cx + ring, Y=cy)
            p.arc(False, cx - ring, cy, -ring, 0.0)
            p.arc(False, cx + ring, cy, ring, 0.0)
        p.retract()
    p.tool(2, "flat end mill D6")
    # A slot across the top, 6 mm deep.
    p.rapid(X=30.0, Y=74.0)
    p.feed(Z=24.0)
    p.feed(X=82.0)
    p.retract()
    # An open slot out through the +x side.
    p.rapid(X=90.0, Y=8.0)
    p.feed(Z=21.0)
    p.feed(X=128.0)
    p.retract()
    p.tool(3, "flat end mill D5, drilling")
    for x, y, z in ((45.0, 80.0, -1.0), (60.0, 84.0, -1.0), (8.0, 20.0, 8.0), (8.0, 70.0, 8.0),
                    (100.0, 30.0, 12.0), (112.0, 40.0, 12.0), (55.0, 33.0, 6.0)):
        p.rapid(X=x, Y=y)
        p.rapid(Z=31.0)
        p.feed(Z=z)
        p.retract()
    tools = [
        {"number": 1, "type": "flat", "diameter": 10, "flute_length": 35},
        {"number": 2, "type": "flat", "diameter": 6, "flute_length": 20},
        {"number": 3, "type": "flat", "diameter": 5, "flute_length": 40},
    ]
    write_part("mech", [0, 0, 0], [124, 92, 30], tools, p.finish())


def frog_depth(x, y):
    """Depth below the top face of the free-form cavity (a face with two eye bumps)."""
    u, v = (x - 55.0) / 38.0, (y - 42.0) / 28.0
    r2 = u * u + v * v
    if r2 >= 1.0:
        return -2.0  # outside: the tool passes above the top face
    bowl = 14.0 * (1.0 - r2) ** 0.8
    eyes = sum(6.0 * math.exp(-((x - ex) ** 2 + (y - 50.0) ** 2) / 40.0) for ex in (42.0, 68.0))
    mouth = 3.0 * math.exp(-((y - 30.0) ** 2) / 6.0) * math.exp(-((x - 55.0) ** 2) / 300.0)
    return bowl - eyes + mouth


def frogface():
    top = 30.0
    p = Program("frogface: ball-end free-form cavity under a flat top")
    p.tool(1, "ball end mill D6")
    y, step = 12.0, 0.9
    forward = True
    while y <= 72.0:
        xs = [15.0 + 0.8 * k for k in range(int((95.0 - 15.0) / 0.8) + 1)]
        if not forward:
            xs.reverse()
        # Only the stretch that dips below the top face, plus one step either side.
        inside = [i for i, x in enumerate(xs) if frog_depth(x, y) > 0.0]
        if inside:
            a, b = max(inside[0] - 1, 0), min(inside[-1] + 1, len(xs) - 1)
            p.polyline([(x, y, top - frog_depth(x, y)) for x in xs[a:b + 1]])
        y = round(y + step, 4)
        forward = not forward
    tools = [{"number": 1, "type": "ball", "diameter": 6, "flute_length": 30}]
    write_part("frogface", [0, 0, 0], [110, 84, 30], tools, p.finish())


def rounded_box_inside(x, y, x0, x1, y0, y1, corner):
    """Signed distance inside a rounded rectangle (positive inside)."""
    qx = abs(x - (x0 + x1) / 2) - ((x1 - x0) / 2 - corner)
    qy = abs(y - (y0 + y1) / 2) - ((y1 - y0) / 2 - corner)
    outside = math.hypot(max(qx, 0.0), max(qy, 0.0)) + min(max(qx, qy), 0.0)
    return corner - outside


def cavity():
    top = 32.0
    p = Program("cavity: every face ball-end finished")
    p.tool(1, "ball end mill D8")

    def tip(x, y):
        inside = rounded_box_inside(x, y, 22.0, 98.0, 16.0, 72.0, 10.0)
        depth = 0.4 + min(16.0, max(0.0, 1.6 * inside))  # 0.4 mm skim of the top face
        return top - depth

    y, forward = -2.0, True
    while y <= 90.0:
        xs = [-2.0 + 0.8 * k for k in range(int(124.0 / 0.8) + 1)]
        if not forward:
            xs.reverse()
        p.polyline([(x, y, tip(x, y)) for x in xs])
        y = round(y + 1.4, 4)
        forward = not forward
    tools = [{"number": 1, "type": "ball", "diameter": 8, "flute_length": 30}]
    write_part("cavity", [0, 0, 0], [120, 88, 32], tools, p.finish())


def impeller():
    blades, hub, tip_r = 7, 14.0, 42.0
    cx, cy = 50.0, 50.0
    thickness = 3.2          # blade thickness, mm
    tool_r = 3.0             # ball D6
    wrap = 0.9               # spiral angle gained from hub to tip, rad

    def floor(r):
        return 30.0 - 0.42 * (r - hub)  # conical hub surface

    def blade_angle(k, r):
        return 2 * math.pi * k / blades + wrap * math.log(r / hub) / math.log(tip_r / hub)

    p = Program("impeller: blades between ball-end channels, 3-axis")
    p.tool(1, "ball end mill D6")
    for k in range(blades):
        passes = 26
        for j in range(passes + 1):
            u = j / passes
            points = []
            r = hub
            while r <= tip_r + 8.0 + 1e-9:
                clear = (thickness / 2 + tool_r) / r
                lo = blade_angle(k, r) + clear
                hi = blade_angle(k + 1, r) - clear
                a = lo + u * (hi - lo)
                points.append((cx + r * math.cos(a), cy + r * math.sin(a), floor(r)))
                r += 0.6
            if j % 2:
                points.reverse()
            p.polyline(points)
    # Free the blade tips: rings around the wheel at the outer floor height.
    z = floor(tip_r + 8.0)
    p.retract()
    p.rapid(X=cx + tip_r + 4.0, Y=cy)
    p.feed(Z=z)
    for ring in (tip_r + 4.0, tip_r + 6.5, tip_r + 9.0):
        p.feed(X=cx + ring, Y=cy)
        p.arc(False, cx - ring, cy, -ring, 0.0)
        p.arc(False, cx + ring, cy, ring, 0.0)
    tools = [{"number": 1, "type": "ball", "diameter": 6, "flute_length": 25}]
    write_part("impeller", [0, 0, 0], [100, 100, 36], tools, p.finish())


def vcarve():
    # Coordinates are kept off round values: with a 90-degree bit a flank |y - y0| = z - z_tip
    # passes exactly through grid nodes when y0 - z_tip is a multiple of the pitch, and rounding
    # then tells a node's state differently on the rays through it.
    top = 20.0
    p = Program("vcarve: V-grooves and chamfers")

    def groove(points):
        """A V-groove through (x, y, depth) points: plunge at the first, cut through the rest."""
        p.polyline([(x, y, top - depth) for x, y, depth in points])
        p.retract()

    p.tool(1, "V-bit 90 degrees D12")
    # Three straight grooves of growing depth (about 3, 5 and 7 mm wide at the top face).
    for k, depth in enumerate((1.53, 2.47, 3.61)):
        groove([(8.17, 50.3 + 9.0 * k, depth), (62.17, 50.3 + 9.0 * k, depth)])
    # A zigzag like a letter W, and a groove that ramps from 0.53 to 3.47 mm deep.
    groove([(10.13, 40.21, 2.13), (17.13, 14.21, 2.13), (24.13, 32.21, 2.13),
            (31.13, 14.21, 2.13), (38.13, 40.21, 2.13)])
    groove([(44.11, 8.23, 0.53), (62.11, 40.23, 3.47)])
    # A circular groove of radius 10 around (82.13, 62.27), cut with two half arcs.
    cx, cy = 82.13, 62.27
    p.retract()
    p.rapid(X=cx + 10.0, Y=cy)
    p.feed(Z=top - 2.07, F=600)
    p.arc(False, cx - 10.0, cy, -10.0, 0.0)
    p.arc(False, cx + 10.0, cy, 10.0, 0.0)
    p.retract()

    p.tool(2, "V-bit 60 degrees D8")
    groove([(70.0, 8.0, 2.5), (96.0, 8.0, 2.5), (96.0, 44.0, 2.5)])

    p.tool(3, "flat end mill D8")
    # A round pocket of radius 9 around (80.07, 26.13), cut ring by ring, 6 mm deep.
    cx, cy, wall = 80.07, 26.13, 9.0
    p.rapid(X=cx, Y=cy)
    p.feed(Z=top - 6.0)
    for ring in (2.0, 5.0):
        p.feed(X=cx + ring, Y=cy)
        p.arc(False, cx - ring, cy, -ring, 0.0)
        p.arc(False, cx + ring, cy, ring, 0.0)
    p.retract()

    p.tool(4, "chamfer mill 90 degrees D10, tip D1")
    # A 1.2 mm chamfer on the pocket's rim: tip 2.5 mm down, so its flank is 1.8 mm off the
    # axis at the chamfer's foot, and the axis runs on a circle 1.8 mm inside the wall.
    ring = wall - 1.8
    p.rapid(X=cx + ring, Y=cy)
    p.feed(Z=top - 2.5)
    p.arc(False, cx - ring, cy, -ring, 0.0)
    p.arc(False, cx + ring, cy, ring, 0.0)
    p.retract()
    # A 1.44 mm chamfer along the stock's top edges: tip 3.07 mm down, 2.13 mm outside each face.
    x0, y0, x1, y1 = -2.13, -2.13, 102.13, 82.13
    p.rapid(X=x0, Y=y0)
    p.feed(Z=top - 3.07)
    for x, y in ((x1, y0), (x1, y1), (x0, y1), (x0, y0)):
        p.feed(X=x, Y=y)
    p.retract()
    tools = [
        {"number": 1, "type": "vbit", "diameter": 12, "tip_angle": 90, "flute_length": 20},
        {"number": 2, "type": "vbit", "diameter": 8, "tip_angle": 60, "flute_length": 20},
        {"number": 3, "type": "flat", "diameter": 8, "flute_length": 25},
        {"number": 4, "type": "vbit", "diameter": 10, "tip_angle": 90, "tip_diameter": 1,
         "flute_length": 15},
    ]
    write_part("vcarve", [0, 0, 0], [100, 80, 20], tools, p.finish())


if __name__ == "__main__":
    mech()
    frogface()
    cavity()
    impeller()
    vcarve()
