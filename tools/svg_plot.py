"""Line plots as SVG for the book's measured figures (chapters 06 to 08), with no plotting library:
the figures are made on a fresh Debian machine from the Python standard library alone.

    from svg_plot import svg_plot   # after sys.path.insert(0, "<repository>/tools")
    Path("plot.svg").write_text(svg_plot(series, "x", "y", "title", log_x=False, log_y=True))
"""

from __future__ import annotations

import math


def svg_plot(series: list[dict], x_label: str, y_label: str, title: str, log_x: bool, log_y: bool) -> str:
    """A line plot: each series {"name", "points": [(x, y)], "colour", "dashed"?}."""
    width, height, left, right, top, bottom = 640, 400, 70, 150, 36, 50
    xs = [x for s in series for x, _ in s["points"]]
    ys = [y for s in series for _, y in s["points"]]
    fx = (lambda v: math.log10(v)) if log_x else (lambda v: v)
    fy = (lambda v: math.log10(v)) if log_y else (lambda v: v)
    x0, x1 = min(map(fx, xs)), max(map(fx, xs))
    y0, y1 = min(map(fy, ys)), max(map(fy, ys))
    if log_y:
        y0, y1 = math.floor(y0), math.ceil(y1)
    else:
        y0, y1 = 0.0, y1 * 1.1
    if log_x:
        x0, x1 = math.floor(x0), math.ceil(x1)
    px = lambda v: left + (fx(v) - x0) / (x1 - x0) * (width - left - right)
    py = lambda v: height - bottom - (fy(v) - y0) / (y1 - y0) * (height - top - bottom)
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" font-family="sans-serif" '
           f'font-size="12">', f'<rect width="{width}" height="{height}" fill="white"/>',
           f'<text x="{width / 2}" y="20" text-anchor="middle" font-size="14">{title}</text>']
    # Axes and ticks: decades on log axes, five steps on linear ones.
    out.append(f'<line x1="{left}" y1="{height - bottom}" x2="{width - right}" y2="{height - bottom}" stroke="black"/>')
    out.append(f'<line x1="{left}" y1="{top}" x2="{left}" y2="{height - bottom}" stroke="black"/>')
    def ticks(a: float, b: float, log: bool) -> list[float]:
        if log:
            return [10.0 ** k for k in range(int(a), int(b) + 1)]
        return [a + (b - a) * k / 5 for k in range(6)]
    for v in ticks(x0, x1, log_x):
        x = px(v)
        out.append(f'<line x1="{x:.1f}" y1="{height - bottom}" x2="{x:.1f}" y2="{height - bottom + 5}" stroke="black"/>')
        out.append(f'<text x="{x:.1f}" y="{height - bottom + 18}" text-anchor="middle">{v:g}</text>')
    for v in ticks(y0, y1, log_y):
        y = py(v)
        out.append(f'<line x1="{left - 5}" y1="{y:.1f}" x2="{left}" y2="{y:.1f}" stroke="black"/>')
        out.append(f'<line x1="{left}" y1="{y:.1f}" x2="{width - right}" y2="{y:.1f}" stroke="#ddd"/>')
        out.append(f'<text x="{left - 8}" y="{y + 4:.1f}" text-anchor="end">{v:.3g}</text>')
    out.append(f'<text x="{(left + width - right) / 2}" y="{height - 12}" text-anchor="middle">{x_label}</text>')
    out.append(f'<text x="16" y="{(top + height - bottom) / 2}" text-anchor="middle" '
               f'transform="rotate(-90 16 {(top + height - bottom) / 2})">{y_label}</text>')
    for i, s in enumerate(series):
        points = sorted(s["points"])
        dash = ' stroke-dasharray="5,4"' if s.get("dashed") else ""
        if s.get("line", True) and len(points) > 1:
            path = " ".join(f"{px(x):.1f},{py(y):.1f}" for x, y in points)
            out.append(f'<polyline points="{path}" fill="none" stroke="{s["colour"]}" stroke-width="2"{dash}/>')
        for x, y in points:
            out.append(f'<circle cx="{px(x):.1f}" cy="{py(y):.1f}" r="3.5" fill="{s["colour"]}"/>')
        ly = top + 10 + 18 * i
        out.append(f'<line x1="{width - right + 10}" y1="{ly}" x2="{width - right + 30}" y2="{ly}" '
                   f'stroke="{s["colour"]}" stroke-width="2"{dash}/>')
        out.append(f'<text x="{width - right + 35}" y="{ly + 4}">{s["name"]}</text>')
    out.append("</svg>")
    return "\n".join(out) + "\n"
