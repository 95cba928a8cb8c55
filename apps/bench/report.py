"""report.html for `navfuse bench`: one self-contained page (plots as base64 PNG, no external
resources) built from the metrics.json and CSVs bench wrote into the report folder.

Usage: python3 report.py DIR   (navfuse runs it with the copy compiled into the binary)

Plots: tracks on an east/north map; errors over time with +-3 sigma envelopes for every pair;
attitude and heading over time; mode timelines. GNSS outages are shaded on every time plot.
Long series are thinned for drawing only (the CSVs keep every sample).
"""
import base64
import csv
import html
import io
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")  # no display: render to memory
import matplotlib.pyplot as plt  # noqa: E402

MAX_POINTS = 20000
COLOURS = {"navfuse": "tab:blue", "device": "tab:orange", "truth": "black"}
MODES = ["invalid", "initializing", "vertical_gyro", "ahrs", "navigation", "dead_reckoning"]


def read_csv(path):
    """Columns of a CSV as lists: floats where they parse, strings otherwise."""
    if not os.path.exists(path):
        return None
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    cols = {}
    if not rows:
        return cols
    for key in rows[0]:
        values = [r[key] for r in rows]
        try:
            cols[key] = [float(v) for v in values]
        except ValueError:
            cols[key] = values
    return cols


def thin(cols):
    """Every n-th row so that a plot has at most MAX_POINTS points."""
    n = len(next(iter(cols.values()))) if cols else 0
    step = max(1, math.ceil(n / MAX_POINTS))
    return {k: v[::step] for k, v in cols.items()} if step > 1 else cols


def png(fig):
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=90, bbox_inches="tight")
    plt.close(fig)
    return base64.b64encode(buf.getvalue()).decode("ascii")


def shade_outages(ax, phases):
    for start, end in phases.get("gnss_outage", []):
        ax.axvspan(start, end, color="tab:red", alpha=0.12, lw=0)


def fmt(v, digits=3):
    if v is None:
        return "-"
    if isinstance(v, float) and math.isnan(v):
        return "-"
    return f"{v:.{digits}f}" if isinstance(v, (int, float)) else html.escape(str(v))


def load_phases(path):
    out = {}
    data = read_csv(path)
    if data:
        for name, start, end in zip(data["phase"], data["start_s"], data["end_s"]):
            out.setdefault(name, []).append((start, end))
    return out


def map_plot(tracks):
    fig, ax = plt.subplots(figsize=(8, 7))
    for name, cols in tracks.items():
        if cols and "east_m" in cols:
            ax.plot(cols["east_m"], cols["north_m"], lw=1.0, color=COLOURS[name], label=name)
    ax.set_xlabel("east [m]")
    ax.set_ylabel("north [m]")
    ax.set_aspect("equal", adjustable="datalim")
    ax.grid(True, alpha=0.3)
    ax.legend()
    ax.set_title("Tracks")
    return png(fig)


def error_plot(name, cols, phases, rows):
    """rows: (title, [(error column, sigma column, label)], unit)."""
    fig, axes = plt.subplots(len(rows), 1, figsize=(11, 2.6 * len(rows)), sharex=True, squeeze=False)
    t = cols["t_s"]
    for ax, (title, series, unit) in zip(axes[:, 0], rows):
        for err_col, sigma_col, label in series:
            err = cols[err_col]
            line, = ax.plot(t, err, lw=0.8, label=label)
            sigma = cols.get(sigma_col)
            if sigma and any(not math.isnan(s) for s in sigma):
                upper = [3 * s for s in sigma]
                ax.fill_between(t, [-u for u in upper], upper, color=line.get_color(), alpha=0.12, lw=0,
                                label=f"±3σ {label}")
        shade_outages(ax, phases)
        ax.set_ylabel(f"{title} [{unit}]")
        ax.grid(True, alpha=0.3)
        ax.legend(loc="upper right", fontsize="small", ncol=3)
    axes[-1, 0].set_xlabel("time since log start [s]")
    axes[0, 0].set_title(f"{name}: errors (estimate − reference), GNSS outages shaded")
    return png(fig)


def attitude_plot(tracks, phases):
    fig, axes = plt.subplots(3, 1, figsize=(11, 7.5), sharex=True)
    for ax, col, label in zip(axes, ["roll_deg", "pitch_deg", "yaw_deg"], ["roll", "pitch", "heading"]):
        for name, cols in tracks.items():
            if cols and col in cols:
                ax.plot(cols["t_s"], cols[col], lw=0.8, color=COLOURS[name], label=name)
        shade_outages(ax, phases)
        ax.set_ylabel(f"{label} [deg]")
        ax.grid(True, alpha=0.3)
        ax.legend(loc="upper right", fontsize="small")
    axes[-1].set_xlabel("time since log start [s]")
    axes[0].set_title("Attitude and heading")
    return png(fig)


def mode_plot(tracks, phases):
    fig, ax = plt.subplots(figsize=(11, 3))
    for i, (name, cols) in enumerate(tracks.items()):
        if not cols or name == "truth":
            continue
        levels = [MODES.index(m) if m in MODES else -1 for m in cols["mode"]]
        ax.step(cols["t_s"], [lv + 0.08 * i for lv in levels], where="post", color=COLOURS[name], label=name)
    shade_outages(ax, phases)
    ax.set_yticks(range(len(MODES)))
    ax.set_yticklabels(MODES)
    ax.set_xlabel("time since log start [s]")
    ax.grid(True, alpha=0.3)
    ax.legend(loc="lower right")
    ax.set_title("Modes (GNSS outages shaded)")
    return png(fig)


METRIC_ROWS = [("horizontal_m", "horizontal [m]"), ("vertical_m", "vertical [m]"), ("position_3d_m", "3-D [m]"),
               ("velocity_mps", "velocity [m/s]"), ("roll_deg", "roll [deg]"), ("pitch_deg", "pitch [deg]"),
               ("heading_deg", "heading [deg]")]


def summary_table(metrics, pairs):
    head = "".join(f"<th colspan=3>{html.escape(p)}<br><small>{metrics[p]['samples']} samples, "
                   f"{fmt(metrics[p]['overlap_s'], 1)} s</small></th>" for p in pairs)
    sub = "".join("<th>RMS</th><th>p95</th><th>max</th>" for _ in pairs)
    body = ""
    for key, label in METRIC_ROWS:
        cells = ""
        for p in pairs:
            m = metrics[p].get(key, {})
            empty = m.get("samples", 1) == 0
            cells += "".join(f"<td>{'-' if empty else fmt(m.get(s))}</td>" for s in ("rms", "p95", "max"))
        body += f"<tr><th>{label}</th>{cells}</tr>"
    return f"<table><tr><th></th>{head}</tr><tr><th></th>{sub}</tr>{body}</table>"


def phase_table(metrics, pairs):
    phases = ["gnss_available", "gnss_outage", "stationary", "moving"]
    rows = ""
    for p in pairs:
        for ph in phases:
            m = metrics[p]["by_phase"][ph]
            if m["samples"] == 0:
                continue
            rows += (f"<tr><td>{p}</td><td>{ph}</td><td>{m['samples']}</td>"
                     + "".join(f"<td>{fmt(m[k]['rms'])}</td>" for k in ("horizontal_m", "vertical_m", "velocity_mps",
                                                                         "heading_deg")) + "</tr>")
        for mode, m in metrics[p]["by_mode"].items():
            rows += (f"<tr><td>{p}</td><td>mode {mode}</td><td>{m['samples']}</td>"
                     + "".join(f"<td>{fmt(m[k]['rms'])}</td>" for k in ("horizontal_m", "vertical_m", "velocity_mps",
                                                                         "heading_deg")) + "</tr>")
    return ("<table><tr><th>pair</th><th>phase</th><th>samples</th><th>horizontal RMS [m]</th>"
            "<th>vertical RMS [m]</th><th>velocity RMS [m/s]</th><th>heading RMS [deg]</th></tr>" + rows + "</table>")


def consistency_table(metrics, pairs):
    rows = ""
    for p in pairs:
        for axis, c in metrics[p]["consistency"].items():
            rows += (f"<tr><td>{p}</td><td>{axis}</td><td>{c['samples']}</td>"
                     + "".join(f"<td>{100 * c[k]:.1f} %</td>" for k in ("within_1sigma", "within_2sigma",
                                                                         "within_3sigma")) + "</tr>")
    if not rows:
        return "<p>No solution reported uncertainties to check.</p>"
    return ("<table><tr><th>pair</th><th>axis</th><th>samples</th><th>within 1σ (68.3 %)</th>"
            "<th>within 2σ (95.4 %)</th><th>within 3σ (99.7 %)</th></tr>" + rows + "</table>")


def timing_table(solutions):
    rows = ""
    for name in ("navfuse", "device"):
        s = solutions.get(name, {})
        if name == "device" and not s.get("present"):
            continue
        rows += (f"<tr><td>{name}</td>" + "".join(f"<td>{fmt(s.get(k), 2)}</td>" for k in (
            "time_to_attitude_s", "time_to_heading_s", "time_to_navigation_s")) + "</tr>")
    return ("<table><tr><th>solution</th><th>to attitude [s]</th><th>to heading [s]</th>"
            "<th>to navigation [s]</th></tr>" + rows + "</table>")


# Marks the page once every image has decoded (naturalWidth > 0) and records script errors, so a
# headless browser can check that the report renders.
RENDER_CHECK = """<script>
window.navfuseErrors = [];
window.addEventListener('error', function (e) { window.navfuseErrors.push(String(e.message)); });
window.addEventListener('load', function () {
  var imgs = Array.prototype.slice.call(document.images);
  var ok = imgs.filter(function (i) { return i.complete && i.naturalWidth > 0; }).length;
  var mark = document.createElement('div');
  mark.id = 'render-check';
  mark.setAttribute('data-images', String(imgs.length));
  mark.setAttribute('data-decoded', String(ok));
  mark.setAttribute('data-errors', String(window.navfuseErrors.length));
  mark.textContent = 'images decoded: ' + ok + ' of ' + imgs.length;
  document.body.appendChild(mark);
});
</script>"""

STYLE = """<style>
body { font-family: sans-serif; margin: 1.5em; color: #222; }
table { border-collapse: collapse; margin: 0.5em 0 1.5em; font-size: 0.9em; }
td, th { border: 1px solid #ccc; padding: 3px 8px; text-align: right; }
th { background: #f2f2f2; }
img { max-width: 100%; display: block; margin: 0.5em 0 1.5em; }
.note { background: #fff4d6; border-left: 4px solid #e0a800; padding: 0.5em 1em; }
#render-check { color: #999; font-size: 0.8em; }
</style>"""


def main(folder):
    with open(os.path.join(folder, "metrics.json")) as f:
        metrics = json.load(f)
    pairs = [k for k in ("navfuse_vs_device", "navfuse_vs_truth", "device_vs_truth", "navfuse_vs_smoothed",
                         "device_vs_smoothed") if k in metrics]
    phases = load_phases(os.path.join(folder, "phases.csv"))
    tracks = {}
    for name in ("navfuse", "device", "truth"):
        cols = read_csv(os.path.join(folder, f"{name}.csv"))
        if cols:
            tracks[name] = thin(cols)

    parts = [f"<h1>navfuse bench</h1><p>{html.escape(', '.join(i['path'] for i in metrics['log']['inputs']))}: "
             f"{fmt(metrics['log']['duration_s'], 1)} s of log, {metrics['log']['imu_samples']} IMU samples, "
             f"phases from {html.escape(metrics['phases']['source'])}, "
             f"{fmt(metrics['phases']['gnss_outage_total_s'], 1)} s in GNSS outages.</p>"]
    for note in metrics.get("notes", []):
        parts.append(f"<p class=note>{html.escape(note)}</p>")
    parts.append("<h2>Summary</h2>" + summary_table(metrics, pairs))
    parts.append("<h2>Time to alignment</h2>" + timing_table(metrics["solutions"]))
    parts.append("<h2>By phase and mode</h2>" + phase_table(metrics, pairs))
    parts.append("<h2>Consistency with reported uncertainty</h2>" + consistency_table(metrics, pairs))

    images = [("Tracks", map_plot(tracks))]
    for p in pairs:
        cols = read_csv(os.path.join(folder, f"{p}.csv"))
        if not cols:
            continue
        cols = thin(cols)
        images.append((f"{p}: position", error_plot(p, cols, phases, [
            ("north", [("err_north_m", "sigma_north_m", "north")], "m"),
            ("east", [("err_east_m", "sigma_east_m", "east")], "m"),
            ("down", [("err_down_m", "sigma_down_m", "down")], "m")])))
        images.append((f"{p}: velocity and attitude", error_plot(p, cols, phases, [
            ("velocity", [("err_vn_mps", "sigma_vn_mps", "north"), ("err_ve_mps", "sigma_ve_mps", "east"),
                          ("err_vd_mps", "sigma_vd_mps", "down")], "m/s"),
            ("roll/pitch", [("err_roll_deg", "sigma_roll_deg", "roll"),
                            ("err_pitch_deg", "sigma_pitch_deg", "pitch")], "deg"),
            ("heading", [("err_heading_deg", "sigma_heading_deg", "heading")], "deg")])))
    images.append(("Attitude and heading", attitude_plot(tracks, phases)))
    images.append(("Modes", mode_plot(tracks, phases)))
    for title, data in images:
        parts.append(f"<h2>{html.escape(title)}</h2><img alt='{html.escape(title)}' src='data:image/png;base64,{data}'>")

    page = ("<!DOCTYPE html><html lang=en><head><meta charset=utf-8><title>navfuse bench report</title>"
            + STYLE + "</head><body>" + "".join(parts) + RENDER_CHECK + "</body></html>")
    tmp = os.path.join(folder, "report.html.tmp")
    with open(tmp, "w", encoding="utf-8") as f:
        f.write(page)
    os.replace(tmp, os.path.join(folder, "report.html"))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: report.py REPORT_DIR")
    main(sys.argv[1])
