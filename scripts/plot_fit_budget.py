#!/usr/bin/env python3
"""Draws bench/run_fit_budget.sh's CSV as an SVG: the compare score (solid) and the orientation
distance / 30° (dashed, the share it adds to the fit's objective) of each scan against the fit's
time budget, with the issue's target (score 0.12, 3° = 0.1) marked. Standard library only.

    scripts/plot_fit_budget.py fit_budget.csv > docs/fit_budget.svg
"""
import csv
import sys

rows = list(csv.DictReader(open(sys.argv[1])))
scans = []
for r in rows:
    if r["scan"] not in scans:
        scans.append(r["scan"])
W, H, L, R, T, B = 560, 300, 56, 150, 20, 44
budgets = sorted({float(r["budget_s"]) for r in rows})
x_max = max(budgets) * 1.05
y_max = max(0.3, max(max(float(r["score"]), float(r["orientation_emd_deg"]) / 30) for r in rows) * 1.1)


def x(v):
    return L + v / x_max * (W - L - R)


def y(v):
    return H - B - v / y_max * (H - T - B)


colours = ["#8c510a", "#01665e", "#762a83", "#b2182b"]
out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" font-family="sans-serif" font-size="11">',
       f'<rect width="{W}" height="{H}" fill="white"/>',
       f'<line x1="{L}" y1="{y(0)}" x2="{W - R}" y2="{y(0)}" stroke="black"/>',
       f'<line x1="{L}" y1="{y(0)}" x2="{L}" y2="{T}" stroke="black"/>']
for b in budgets:
    out.append(f'<line x1="{x(b):.1f}" y1="{y(0)}" x2="{x(b):.1f}" y2="{y(0) + 4}" stroke="black"/>')
    out.append(f'<text x="{x(b):.1f}" y="{y(0) + 16}" text-anchor="middle">{b:g}</text>')
tick = 0.0
while tick <= y_max + 1e-9:
    out.append(f'<line x1="{L - 4}" y1="{y(tick):.1f}" x2="{L}" y2="{y(tick):.1f}" stroke="black"/>')
    out.append(f'<text x="{L - 6}" y="{y(tick) + 4:.1f}" text-anchor="end">{tick:.2f}</text>')
    tick += 0.05
out.append(f'<line x1="{L}" y1="{y(0.12):.1f}" x2="{W - R}" y2="{y(0.12):.1f}" stroke="#999" stroke-dasharray="2,3"/>')
out.append(f'<text x="{W - R - 4}" y="{y(0.12) - 4:.1f}" text-anchor="end" fill="#666">target score 0.12</text>')
out.append(f'<line x1="{L}" y1="{y(0.1):.1f}" x2="{W - R}" y2="{y(0.1):.1f}" stroke="#999" stroke-dasharray="1,5"/>')
out.append(f'<text x="{W - R - 4}" y="{y(0.1) + 12:.1f}" text-anchor="end" fill="#666">target 3° / 30°</text>')
out.append(f'<text x="{(L + W - R) / 2}" y="{H - 8}" text-anchor="middle">time budget (s), 2-core machine</text>')
out.append(f'<text x="14" y="{(T + H - B) / 2}" text-anchor="middle" transform="rotate(-90 14 {(T + H - B) / 2})">compare score</text>')
for i, scan in enumerate(scans):
    c = colours[i % len(colours)]
    pts = sorted((float(r["budget_s"]), float(r["score"]), float(r["orientation_emd_deg"])) for r in rows if r["scan"] == scan)
    out.append('<polyline fill="none" stroke="%s" stroke-width="2" points="%s"/>' % (c, " ".join(f"{x(b):.1f},{y(s):.1f}" for b, s, _ in pts)))
    out.append('<polyline fill="none" stroke="%s" stroke-width="1.5" stroke-dasharray="5,3" points="%s"/>' % (c, " ".join(f"{x(b):.1f},{y(e / 30):.1f}" for b, _, e in pts)))
    for b, s, _ in pts:
        out.append(f'<circle cx="{x(b):.1f}" cy="{y(s):.1f}" r="3" fill="{c}"/>')
    name = scan.split("_polyhaven")[0].replace("_", " ")
    ly = T + 14 + 34 * i
    out.append(f'<line x1="{W - R + 10}" y1="{ly}" x2="{W - R + 30}" y2="{ly}" stroke="{c}" stroke-width="2"/>')
    out.append(f'<text x="{W - R + 34}" y="{ly + 4}">{name} score</text>')
    out.append(f'<line x1="{W - R + 10}" y1="{ly + 14}" x2="{W - R + 30}" y2="{ly + 14}" stroke="{c}" stroke-dasharray="5,3"/>')
    out.append(f'<text x="{W - R + 34}" y="{ly + 18}">EMD / 30°</text>')
out.append("</svg>")
print("\n".join(out))
