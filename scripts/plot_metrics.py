#!/usr/bin/env python3
"""Plots a `tessera metrics` report as an SVG: the pair correlation function of
every class pair (exemplar solid, output dashed) and the synthesis energy per
iteration read from the output's "stats". Standard library only.

usage: plot_metrics.py REPORT.json OUTPUT.json PLOT.svg [TITLE]
"""
import json
import math
import sys

COLORS = ["#4e79a7", "#f28e2b", "#e15759", "#76b7b2", "#59a14f", "#edc948", "#b07aa1", "#ff9da7"]


def polyline(xs, ys, x0, y0, w, h, xmax, ymax, color, dash=""):
    pts = []
    for x, y in zip(xs, ys):
        if y is None or not math.isfinite(y):
            continue
        px = x0 + w * x / xmax
        py = y0 + h - h * min(y, ymax) / ymax
        pts.append(f"{px:.1f},{py:.1f}")
    if len(pts) < 2:
        return ""
    d = f' stroke-dasharray="{dash}"' if dash else ""
    return f'<polyline fill="none" stroke="{color}" stroke-width="1.6"{d} points="{" ".join(pts)}"/>\n'


def axes(x0, y0, w, h, xmax, ymax, xlabel, ylabel, title):
    s = f'<rect x="{x0}" y="{y0}" width="{w}" height="{h}" fill="none" stroke="#888"/>\n'
    s += f'<text x="{x0 + w / 2}" y="{y0 + h + 32}" text-anchor="middle" font-size="12">{xlabel}</text>\n'
    s += f'<text x="{x0 - 38}" y="{y0 + h / 2}" text-anchor="middle" font-size="12" '
    s += f'transform="rotate(-90 {x0 - 38} {y0 + h / 2})">{ylabel}</text>\n'
    s += f'<text x="{x0 + w / 2}" y="{y0 - 8}" text-anchor="middle" font-size="13">{title}</text>\n'
    for k in range(5):
        xv = xmax * k / 4
        yv = ymax * k / 4
        s += f'<text x="{x0 + w * k / 4}" y="{y0 + h + 15}" text-anchor="middle" font-size="10">{xv:.3g}</text>\n'
        s += f'<text x="{x0 - 5}" y="{y0 + h - h * k / 4 + 3}" text-anchor="end" font-size="10">{yv:.3g}</text>\n'
    return s


def main():
    report = json.load(open(sys.argv[1]))
    output = json.load(open(sys.argv[2]))
    title = sys.argv[4] if len(sys.argv) > 4 else ""
    ex_pcf, out_pcf = report["exemplar"]["pcf"], report["output"]["pcf"]
    r = ex_pcf["r"]
    ymax = 0.0
    for p in ex_pcf["pairs"] + out_pcf["pairs"]:
        ymax = max([ymax] + [v for v in p["g"][1:] if v is not None and math.isfinite(v)])
    ymax = max(1.5, min(ymax * 1.05, 8.0))
    W, H = 820, 330
    svg = f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" font-family="sans-serif">\n'
    svg += f'<rect width="{W}" height="{H}" fill="white"/>\n'
    x0, y0, w, h = 60, 30, 430, 250
    err = report.get("pcf_relative_error")
    err_text = f"relative error {err:.3f}" if isinstance(err, (int, float)) else ""
    svg += axes(x0, y0, w, h, r[-1], ymax, "r", "g(r)", f"{title}: pair correlation ({err_text})")
    for k, (pe, po) in enumerate(zip(ex_pcf["pairs"], out_pcf["pairs"])):
        c = COLORS[k % len(COLORS)]
        svg += polyline(r, pe["g"], x0, y0, w, h, r[-1], ymax, c)
        svg += polyline(out_pcf["r"], po["g"], x0, y0, w, h, r[-1], ymax, c, "5,3")
        label = pe["a"] if pe["a"] == pe["b"] else f'{pe["a"]}-{pe["b"]}'
        svg += f'<text x="{x0 + w - 8}" y="{y0 + 16 + 14 * k}" text-anchor="end" font-size="11" fill="{c}">{label}</text>\n'
    svg += f'<text x="{x0 + 8}" y="{y0 + 16}" font-size="11">solid: exemplar, dashed: output</text>\n'
    energy = output.get("stats", {}).get("energy", [])
    if energy:
        ex0, ew = 580, 210
        emax = max(energy) * 1.05
        svg += axes(ex0, y0, ew, h, max(1, len(energy) - 1), emax, "iteration", "energy (Eq. 2)", "energy")
        svg += polyline(list(range(len(energy))), energy, ex0, y0, ew, h, max(1, len(energy) - 1), emax, "#333")
    svg += "</svg>\n"
    with open(sys.argv[3], "w") as f:
        f.write(svg)


if __name__ == "__main__":
    main()
