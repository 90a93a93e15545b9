#!/usr/bin/env python3
"""Writes indicator.svg beside this file: the radial-alignment check of DIN 3968 as an inspector
makes it (docs/inspection.md, "Radial alignment"). Standard library only; run it with
`python3 docs/inspection/indicator.py`.

The plane of the drawing is square to the hob axis. The nominal face line runs at the rake offset
e from the axis; the actual face is the nominal one moved out of the tooth by u (excess material).
The reference line is the nominal line turned about the hob axis until it passes through the
actual face's tip point; the indicator is zeroed there and run down to the root. The sizes are
exaggerated so that the readings can be seen; the geometry is exact for them.
"""
import math
import os

# The face, mm (exaggerated: u is a few hundredths of a mm on a real hob).
E = 5.0        # rake offset e
U = 4.0        # the face moved out of the tooth (excess material)
R_TIP = 40.0   # r_a, the tip radius measured
R_ROOT = 19.0  # the root radius measured
STATIONS = 5   # indicator positions, tip to root

# The model: the hob axis at the origin; the nominal line has its foot at (e, 0) and runs along +y,
# the tooth on its +x side (the outward normal, excess material, points to -x). On the page the line
# runs to the right and the tooth lies below it: 14 px per mm, the hob axis at (50, 215) px.
SCALE, OX, OY = 14.0, 50.0, 215.0
WIDTH, HEIGHT = 700, 500


def px(p):
    return OX + SCALE * p[1], OY + SCALE * p[0]


def add(a, b, f=1.0):
    return a[0] + f * b[0], a[1] + f * b[1]


out = []


def line(a, b, cls, extra=""):
    (x1, y1), (x2, y2) = px(a), px(b)
    out.append(f'<line x1="{x1:.1f}" y1="{y1:.1f}" x2="{x2:.1f}" y2="{y2:.1f}" class="{cls}"{extra}/>')


def text(p, s, cls="label", anchor="start", dx=0.0, dy=0.0):
    x, y = px(p)
    out.append(f'<text x="{x + dx:.1f}" y="{y + dy:.1f}" text-anchor="{anchor}" class="{cls}">{s}</text>')


def dot(p, colour, radius=3.5):
    x, y = px(p)
    out.append(f'<circle cx="{x:.1f}" cy="{y:.1f}" r="{radius}" fill="{colour}"/>')


def arc(radius, x_from, x_to, cls):
    """The circle about the hob axis between the model's x = x_from and x = x_to (y > 0)."""
    pts = []
    for k in range(41):
        x = x_from + (x_to - x_from) * k / 40
        pts.append(px((x, math.sqrt(radius ** 2 - x ** 2))))
    d = " ".join(f"{'M' if k == 0 else 'L'} {X:.1f} {Y:.1f}" for k, (X, Y) in enumerate(pts))
    out.append(f'<path d="{d}" class="{cls}"/>')


def dimension(a, b, label, side, offset, anchor="middle", dx=0.0, dy=0.0):
    """A dimension from a to b drawn `offset` mm along the unit vector `side`, with end ticks."""
    a2, b2 = add(a, side, offset), add(b, side, offset)
    line(a, add(a, side, offset * 1.2), "ext")
    line(b, add(b, side, offset * 1.2), "ext")
    line(a2, b2, "dim", ' marker-start="url(#tick)" marker-end="url(#tick)"')
    text(((a2[0] + b2[0]) / 2, (a2[1] + b2[1]) / 2), label, "label", anchor, dx, dy)


s_tip = math.sqrt(R_TIP ** 2 - E ** 2)
s_root = math.sqrt(R_ROOT ** 2 - E ** 2)
x_act = E - U                                       # the actual face: x = e - u
tip = (x_act, math.sqrt(R_TIP ** 2 - x_act ** 2))   # its tip point
root = (x_act, math.sqrt(R_ROOT ** 2 - x_act ** 2))
# The reference line: the nominal one turned by phi about the axis, through the actual tip point.
phi = math.atan2(tip[1], tip[0]) - math.atan2(s_tip, E)
t_ref = (math.cos(phi), math.sin(phi))   # across the line, into the tooth
a_ref = (-math.sin(phi), math.cos(phi))  # along the line, toward the tip
foot_ref = (E * t_ref[0], E * t_ref[1])

out.append(f'<svg xmlns="http://www.w3.org/2000/svg" width="{WIDTH}" height="{HEIGHT}" '
           f'viewBox="0 0 {WIDTH} {HEIGHT}" font-family="sans-serif">')
out.append("""<defs>
<marker id="arrow" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="7" markerHeight="7" orient="auto-start-reverse">
<path d="M 0 0 L 10 5 L 0 10 z" fill="#c0392b"/></marker>
<marker id="travel" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="8" markerHeight="8" orient="auto-start-reverse">
<path d="M 0 0 L 10 5 L 0 10 z" fill="#555"/></marker>
<marker id="tick" viewBox="0 0 10 10" refX="5" refY="5" markerWidth="9" markerHeight="9" orient="auto">
<path d="M 5 0 L 5 10" stroke="#555" stroke-width="1.5"/></marker>
</defs>
<style>
.nominal { stroke: #888; stroke-width: 1.5; stroke-dasharray: 7 5; fill: none; }
.actual { stroke: #111; stroke-width: 3; fill: none; }
.reference { stroke: #1f5fbf; stroke-width: 2; fill: none; }
.foot { stroke: #1f5fbf; stroke-width: 1; stroke-dasharray: 3 4; fill: none; }
.circle { stroke: #999; stroke-width: 1; fill: none; }
.reading { stroke: #c0392b; stroke-width: 2; }
.dim { stroke: #555; stroke-width: 1; }
.ext { stroke: #bbb; stroke-width: 0.8; }
.travel { stroke: #555; stroke-width: 1.5; }
.label { font-size: 16px; fill: #222; }
.small { font-size: 14px; fill: #444; }
.red { font-size: 14px; fill: #c0392b; }
.blue { font-size: 14px; fill: #1f5fbf; }
</style>
<rect width="100%" height="100%" fill="white"/>""")

# The tooth below the face, the gash above it.
text((-9, 24), "gash", "label", "middle")
text((-9, 24), "excess material reads plus", "small", "middle", dy=18)
text((6.5, 27), "tooth", "label", "middle")

# Tip and root circles about the hob axis.
arc(R_TIP, -11, 7.5, "circle")
arc(R_ROOT, -11, 7.5, "circle")
text((-11, math.sqrt(R_TIP ** 2 - 121)), "tip circle, r_a", "small", "middle", dy=-8)
text((-11, math.sqrt(R_ROOT ** 2 - 121)), "root circle, r_root", "small", "middle", dy=-8)

# The nominal line (from its foot, past the tip), the actual face (root to tip), the reference line.
line((E, 0), (E, s_tip + 2.5), "nominal")
line(add(root, (0, -1.5)), add(tip, (0, 1.5)), "actual")
line(foot_ref, add(foot_ref, a_ref, s_tip + 2.5), "reference")
line((0, 0), foot_ref, "foot")

# The hob axis, square to the page, and e.
x0, y0 = px((0, 0))
out.append(f'<circle cx="{x0}" cy="{y0}" r="8" fill="white" stroke="#111" stroke-width="1.5"/>')
out.append(f'<circle cx="{x0}" cy="{y0}" r="2.5" fill="#111"/>')
text((0, 0), "hob axis O", "label", "start", dx=-30, dy=-16)
text((0, 0), "(square to the page)", "small", "start", dx=56, dy=-16)
dimension((0, 0), (E, 0), "e", (0, -1), 2.2, "end", dx=-6, dy=5)
text((E, 0), "foot (s = 0)", "small", "start", dx=-8, dy=22)

# The actual tip point, where the indicator is set to zero; u beyond the tip.
dot(tip, "#1f5fbf", 4.5)
label_at = add(tip, (6.2, -1.5))
line(tip, add(label_at, (-0.9, 0.3)), "dim")
text(label_at, "actual tip point: indicator set to 0", "blue", "end", dx=0, dy=0)
dimension((E, s_tip + 2.5), (x_act, s_tip + 2.5), "u", (0, 1), 1.2, "start", dx=8, dy=5)

# The indicator stations, tip to root, along the reference line: the reading is the actual face's
# offset across the reference line, plus out of the tooth (upward on the page).
labels = {2: "u (1 - s / s_tip)", STATIONS - 1: "u (1 - s_root / s_tip)"}
for k in range(STATIONS):
    s = s_tip - (s_tip - s_root) * k / (STATIONS - 1)
    q = add(foot_ref, a_ref, s)
    lam = (q[0] - x_act) / t_ref[0]  # q - lam t_ref lies on x = x_act
    hit = add(q, t_ref, -lam)
    dot(q, "#1f5fbf")
    if lam * SCALE > 4:
        line(q, hit, "reading", ' marker-end="url(#arrow)"')
    if k in labels:
        text(hit, labels[k], "red", "middle", dy=-10)

# s, along the reference line from its foot to the middle station.
s_mid = s_tip - (s_tip - s_root) * 2 / (STATIONS - 1)
dimension(foot_ref, add(foot_ref, a_ref, s_mid), "s = √(r² - e²)", t_ref, 2.6, "middle", dy=22)

# The indicator's travel, tip to root, in the gash above the face.
line((-3.2, s_tip - 1), (-3.2, s_root + 1), "travel", ' marker-end="url(#travel)"')
text((-3.2, (s_tip + s_root) / 2), "indicator run along the reference line, tip to root", "small", "middle", dy=-8)

# The legend.
lx, ly = 60, 392
items = [("nominal", "nominal face line, offset e from the hob axis O"),
         ("actual", "actual face (here moved out of the tooth by u)"),
         ("reference", "reference line: the nominal line turned about O through the actual tip point"),
         ("reading", "indicator reading d(s) - d(s_tip) s / s_tip, plus = excess material")]
out.append(f'<rect x="{lx - 12}" y="{ly - 20}" width="{WIDTH - 2 * lx + 36}" height="{22 * len(items) + 10}" '
           'fill="white" stroke="#ccc"/>')
for k, (cls, words) in enumerate(items):
    y = ly + 22 * k
    out.append(f'<line x1="{lx}" y1="{y - 5}" x2="{lx + 34}" y2="{y - 5}" class="{cls}"/>')
    out.append(f'<text x="{lx + 42}" y="{y}" class="small">{words}</text>')
out.append(f'<text x="{WIDTH - 12}" y="{HEIGHT - 10}" text-anchor="end" class="small">'
           'The plane square to the hob axis; sizes exaggerated (e = 5 mm, u = 4 mm).</text>')
out.append("</svg>")

path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "indicator.svg")
with open(path, "w", encoding="utf-8") as f:
    f.write("\n".join(out) + "\n")
