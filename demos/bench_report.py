#!/usr/bin/python3
"""The benchmark report, from what demos/bench_timedemo.sh measured.

usage: bench_report.py --summary-only DIR          summary.md only (no matplotlib needed)
       bench_report.py DIR [--gallery GDIR] [--machine FILE.json] [--images IDIR]
                                                     report.html (self-contained: charts and
                                                     pictures as base64 PNG), report.md and
                                                     the charts as PNG files in IDIR
                                                     (default DIR/images)

DIR holds results.jsonl (one record per run) and frames/ (each run's frame times). A run that
failed is counted as failed and never contributes a number. Ratios compare medians over the
runs of one cell (demo x resolution); a ratio is shown only when both medians exist.
"""
import argparse
import base64
import html
import io
import json
import os
import statistics
import sys

PEER = "quakespasm"
BASELINE = "classic"


def load_records(directory):
    path = os.path.join(directory, "results.jsonl")
    with open(path) as f:
        return [json.loads(line) for line in f if line.strip()]


def column_of(record):
    return PEER if record["engine"] == PEER else record["plugin"]


def ordered(values, first):
    """Unique values in order of appearance, `first` (if present) leading."""
    seen = []
    for v in values:
        if v not in seen:
            seen.append(v)
    return sorted(seen, key=lambda v: (v != first, seen.index(v)))


class Cell:
    """One column (style or peer) on one demo at one resolution, over the rounds."""

    def __init__(self):
        self.fps = []
        self.failed = 0
        self.failures = []
        self.records = []  # the -benchjson records of the runs that worked
        self.frame_files = []
        self.startup = []
        self.tails = []  # (99th / median, 1% low / average fps) per run that has frame times
        self.tails_failed = 0  # runs that worked whose frame times were asked for and not had

    def add(self, r):
        if r.get("failed") or r.get("fps") is None:
            self.failed += 1
            self.failures.append(r.get("failure") or "failed")
            return
        self.fps.append(r["fps"])
        if r.get("record"):
            self.records.append(r["record"])
        if r.get("frames_file"):
            self.frame_files.append(r["frames_file"])
        if r.get("startup_s") is not None:
            self.startup.append(r["startup_s"])
        tail = tail_of(r)
        if tail:
            self.tails.append(tail)
        elif (r.get("tail") or {}).get("failed"):
            self.tails_failed += 1

    def median(self):
        return statistics.median(self.fps) if self.fps else None

    def percentile_median(self, field):
        values = [rec[field] for rec in self.records if field in rec]
        return statistics.median(values) if values else None


def tail_of(r):
    """(99th / median, 1% low / average) of one run: ours from its -benchjson record,
    QuakeSpasm's from quakespasm_tail.sh's figures (bench_timedemo.sh --peer-tail)."""
    rec = r.get("record") or {}
    if rec.get("median_ms") and rec.get("p99_ms") and rec.get("fps"):
        return rec["p99_ms"] / rec["median_ms"], rec.get("low1_fps", 0) / rec["fps"]
    tail = r.get("tail") or {}
    if tail.get("median_ms") and tail.get("p99_ms") and tail.get("avg_fps"):
        return tail["p99_ms"] / tail["median_ms"], tail["low1_fps"] / tail["avg_fps"]
    return None


# Issue 19's targets for a smooth game: the slow frames no slower than this, relative to the run.
TAIL_MAX_P99_OVER_MEDIAN = 2.5
TAIL_MIN_LOW_OVER_AVG = 0.4
TAIL_NOTE = ("Frame-time tail per run, in run order: the 99th-percentile frame over the median "
             "frame, and the 1%% low (average fps over the slowest 1%% of frames) over the average "
             "fps. A run meets the targets at 99th/median <= %.1f and 1%% low/avg >= %.1f. "
             "QuakeSpasm's come from its host_speeds log (whole milliseconds), with "
             "bench_timedemo.sh --peer-tail." % (TAIL_MAX_P99_OVER_MEDIAN, TAIL_MIN_LOW_OVER_AVG))
TAIL_HEADER = ["demo", "size", "engine / style", "99th/median per run", "1% low/avg per run",
               "runs meeting both"]


def tail_rows(records, cells):
    rows = []
    for key in cell_keys(records):
        for column in columns_of(records):
            c = cells[key].get(column)
            if c is None or not (c.tails or c.tails_failed):
                continue
            met = sum(1 for p99, low in c.tails
                      if p99 <= TAIL_MAX_P99_OVER_MEDIAN and low >= TAIL_MIN_LOW_OVER_AVG)
            unmeasured = ", %d without frame times (see logs/)" % c.tails_failed \
                if c.tails_failed else ""
            rows.append([key[0], key[1], column, ", ".join("%.2f" % t[0] for t in c.tails),
                         ", ".join("%.2f" % t[1] for t in c.tails),
                         "%d of %d%s" % (met, len(c.tails) + c.tails_failed, unmeasured)])
    return rows


def collect(records):
    cells = {}
    for r in records:
        key = (r["demo"], r["res"])
        cells.setdefault(key, {}).setdefault(column_of(r), Cell()).add(r)
    return cells


def columns_of(records):
    return ordered([column_of(r) for r in records], BASELINE)


def cell_keys(records):
    return ordered([(r["demo"], r["res"]) for r in records], None)


def ratio_text(value, reference):
    if value is None or reference is None or reference == 0:
        return "-"
    return "%.2fx" % (value / reference)


def fmt(value, pattern="%.1f"):
    return "-" if value is None else pattern % value


def summary_rows(records, cells):
    """Rows of the fps table: one per cell and column."""
    rows = []
    for key in cell_keys(records):
        by_column = cells[key]
        classic = by_column.get(BASELINE).median() if BASELINE in by_column else None
        peer = by_column.get(PEER).median() if PEER in by_column else None
        for column in columns_of(records):
            if column not in by_column:
                continue
            c = by_column[column]
            spread = "%.1f–%.1f" % (min(c.fps), max(c.fps)) if c.fps else "-"
            frame_ms = "-"
            if c.records:
                frame_ms = "%s / %s / %s" % tuple(
                    fmt(c.percentile_median(f), "%.2f") for f in ("median_ms", "p95_ms", "p99_ms"))
            rows.append([key[0], key[1], column, "%d" % len(c.fps),
                         "%d" % c.failed if c.failed else "", fmt(c.median()), spread, frame_ms,
                         ratio_text(c.median(), classic) if column != PEER else "-",
                         ratio_text(c.median(), peer) if column != PEER else "-"])
    return rows


SUMMARY_HEADER = ["demo", "size", "engine / style", "runs", "failed", "median fps",
                  "min–max fps", "frame ms: median / 95th / 99th", "vs classic",
                  "vs QuakeSpasm"]


def markdown_table(header, rows):
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(row) + " |" for row in rows]
    return "\n".join(lines)


def failure_lines(records, cells):
    out = []
    for key in cell_keys(records):
        for column, c in cells[key].items():
            for why in c.failures:
                out.append("- %s %s %s: FAILED (%s)" % (key[0], key[1], column, why))
    return out


def write_summary(directory, records, cells):
    text = markdown_table(SUMMARY_HEADER, summary_rows(records, cells)) + "\n"
    failures = failure_lines(records, cells)
    if failures:
        text += "\nFailed runs (no number reported for them):\n\n" + "\n".join(failures) + "\n"
    tails = tail_rows(records, cells)
    if tails:
        text += "\n" + TAIL_NOTE + "\n\n" + markdown_table(TAIL_HEADER, tails) + "\n"
    with open(os.path.join(directory, "summary.md"), "w") as f:
        f.write(text)
    print(text, end="")


# ---- charts (matplotlib, imported only when they are drawn)

def read_frame_times(directory, files):
    values = []
    for name in files:
        with open(os.path.join(directory, name)) as f:
            values += [float(line) for line in f if line.strip() and not line.startswith("#")]
    return values


def figure_png(fig):
    buffer = io.BytesIO()
    fig.savefig(buffer, format="png", dpi=80, bbox_inches="tight")
    return buffer.getvalue()


def fps_chart(plt, records, cells):
    keys = cell_keys(records)
    columns = columns_of(records)
    fig, ax = plt.subplots(figsize=(max(5, 1.6 * len(keys) * len(columns) / 2 + 2), 3.6))
    width = 0.8 / len(columns)
    for i, column in enumerate(columns):
        xs, medians, low, high = [], [], [], []
        for k, key in enumerate(keys):
            c = cells[key].get(column)
            x = k + (i - (len(columns) - 1) / 2) * width
            if c is None:
                continue
            if not c.fps:
                ax.text(x, 0, "failed", rotation=90, ha="center", va="bottom", fontsize=8)
                continue
            m = c.median()
            xs.append(x)
            medians.append(m)
            low.append(m - min(c.fps))
            high.append(max(c.fps) - m)
        ax.bar(xs, medians, width, yerr=[low, high], capsize=3, label=column)
    ax.set_xticks(range(len(keys)))
    ax.set_xticklabels(["%s %s" % key for key in keys])
    ax.set_ylabel("fps (median, whiskers min–max)")
    ax.set_title("timedemo frame rate")
    ax.legend(fontsize=8)
    ax.grid(axis="y", alpha=0.3)
    return figure_png(fig)


def cdf_chart(plt, directory, records, cells):
    keys = cell_keys(records)
    fig, axes = plt.subplots(1, len(keys), figsize=(4.2 * len(keys), 3.4), squeeze=False)
    for ax, key in zip(axes[0], keys):
        top = 0
        for column in columns_of(records):
            c = cells[key].get(column)
            if c is None or not c.frame_files:
                continue
            times = sorted(read_frame_times(directory, c.frame_files))
            if not times:
                continue
            n = len(times)
            ax.plot(times, [(i + 1) / n for i in range(n)], label="%s (%d frames)" % (column, n))
            top = max(top, times[min(n - 1, int(n * 0.995))])
        ax.set_xlim(0, top * 1.05 if top else 1)
        ax.set_xlabel("frame time (ms)")
        ax.set_ylabel("share of frames at most this long")
        ax.set_title("%s %s" % key)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, loc="lower right")
    fig.suptitle("frame-time distribution (all rounds pooled; x axis to the 99.5th percentile)",
                 fontsize=9)
    return figure_png(fig)


def startup_chart(plt, records, cells):
    columns = [c for c in columns_of(records) if c != PEER]
    values = {col: [] for col in columns}
    for key in cell_keys(records):
        for col in columns:
            if col in cells[key]:
                values[col] += cells[key][col].startup
    columns = [c for c in columns if values[c]]
    if not columns:
        return None
    fig, ax = plt.subplots(figsize=(1.2 * len(columns) + 2.5, 3.0))
    medians = [statistics.median(values[c]) for c in columns]
    low = [m - min(values[c]) for m, c in zip(medians, columns)]
    high = [max(values[c]) - m for m, c in zip(medians, columns)]
    ax.bar(range(len(columns)), medians, yerr=[low, high], capsize=3)
    ax.set_xticks(range(len(columns)))
    ax.set_xticklabels(columns)
    ax.set_ylabel("seconds (median, min–max)")
    ax.set_title("start-up to first frame (nprquake)")
    ax.grid(axis="y", alpha=0.3)
    return figure_png(fig)


def gpu_pass_means(cell):
    """Mean GPU ms per frame of each timed pass over the cell's runs ({} when none timed)."""
    per_pass = {}
    for record in cell.records:
        if not record.get("gpu_timing"):
            continue
        for name, values in (record.get("gpu_passes") or {}).items():
            if values.get("count"):
                per_pass.setdefault(name, []).append(values["ms_per_frame"])
    return {name: statistics.mean(v) for name, v in per_pass.items()}


def gpu_chart(plt, records, cells):
    """Stacked bars: per demo, size and style, the mean GPU time per frame of each pass."""
    bars, passes = [], []
    for key in cell_keys(records):
        for column in columns_of(records):
            c = cells[key].get(column)
            if c is None or column == PEER:
                continue
            means = gpu_pass_means(c)
            if means:
                bars.append(("%s %s\n%s" % (key[0], key[1], column), means))
                passes += [p for p in means if p not in passes]
    if not bars:
        return None
    fig, ax = plt.subplots(figsize=(max(5, 1.15 * len(bars) + 2), 3.8))
    bottoms = [0.0] * len(bars)
    for name in passes:
        heights = [means.get(name, 0.0) for _, means in bars]
        ax.bar(range(len(bars)), heights, 0.7, bottom=bottoms, label=name)
        bottoms = [b + h for b, h in zip(bottoms, heights)]
    ax.set_xticks(range(len(bars)))
    ax.set_xticklabels([label for label, _ in bars], fontsize=7)
    ax.set_ylabel("GPU ms per frame (mean over runs)")
    ax.set_title("GPU time per pass (timer queries)")
    ax.legend(fontsize=7, ncol=2)
    ax.grid(axis="y", alpha=0.3)
    return figure_png(fig)


def startup_rows(records, cells):
    rows = []
    for column in [c for c in columns_of(records) if c != PEER]:
        values = []
        for key in cell_keys(records):
            if column in cells[key]:
                values += cells[key][column].startup
        if values:
            rows.append([column, "%d" % len(values), "%.2f" % statistics.median(values),
                         "%.2f–%.2f" % (min(values), max(values))])
    return rows


def gallery_images(gallery):
    """(caption, path) of every PNG in the gallery directory, as <demo>_f<frame>_<style>.png."""
    if not gallery or not os.path.isdir(gallery):
        return []
    out = []
    for name in sorted(os.listdir(gallery)):
        if name.endswith(".png"):
            out.append((name[:-4].replace("_", " "), os.path.join(gallery, name)))
    return out


QUALITY_HEADER = ["demo", "size", "style", "frame", "recall", "precision", "on models",
                  "flicker: lines", "outlines", "excess (frames)"]


def load_quality(directory):
    """The line-quality records benchmark.sh wrote (edgequality), [] when there are none."""
    path = os.path.join(directory, "quality.jsonl")
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return [json.loads(line) for line in f if line.strip()]


def quality_rows(quality):
    rows = []
    for q in quality:
        s, fl = q["silhouettes"], q["flicker"]
        rows.append([q["demo"], q["size"], q["style"], str(q["first_frame"]),
                     "%.3f" % s["recall"], "%.3f" % s["precision"], "%.3f" % s["on_models"],
                     "%.3f" % fl["lines"], "%.3f" % fl["outlines"],
                     "%+.3f (%d)" % (fl["excess"], fl["frames"])])
    return rows


QUALITY_NOTE = ("Line quality (bin/edgequality, the measure the tests use): the style's silhouettes "
                "over its object-id reference (tech_shading 3) of the same paused frame; recall = "
                "outline pixels with a line within 1 px, precision = line pixels within 2 px of an "
                "outline (inner folds of a model count against it), on models = within 2 px of a "
                "model; flicker = share of line pixels that appear or vanish (no line within 1 px in "
                "the other frame) between consecutive frames, against the same for the reference's "
                "outlines. Only technical draws lines.")


def machine_rows(machine, records):
    rows = [[k, str(v)] for k, v in machine.items()]
    renderers = ordered([r["record"]["gl_renderer"] for r in records if r.get("record")], None)
    rows.append(["GL_RENDERER (nprquake)", "; ".join(renderers) or "-"])
    return rows


def html_table(header, rows):
    head = "".join("<th>%s</th>" % html.escape(h) for h in header)
    body = "".join("<tr>%s</tr>" % "".join("<td>%s</td>" % html.escape(c) for c in row)
                   for row in rows)
    return "<table><tr>%s</tr>%s</table>" % (head, body)


def img_tag(png, alt):
    return '<img alt="%s" src="data:image/png;base64,%s">' % (
        html.escape(alt), base64.b64encode(png).decode())


def write_report(directory, records, cells, gallery, machine, images):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    os.makedirs(images, exist_ok=True)
    charts = [("bench_fps.png", "frame rate per demo, size and style",
               fps_chart(plt, records, cells)),
              ("bench_frametime_cdf.png", "frame-time distribution per style",
               cdf_chart(plt, directory, records, cells))]
    gpu = gpu_chart(plt, records, cells)
    if gpu:
        charts.append(("bench_gpu_passes.png", "GPU time per pass", gpu))
    startup = startup_chart(plt, records, cells)
    if startup:
        charts.append(("bench_startup.png", "start-up to first frame", startup))
    for name, _, png in charts:
        with open(os.path.join(images, name), "wb") as f:
            f.write(png)
    pictures = gallery_images(gallery)

    summary = markdown_table(SUMMARY_HEADER, summary_rows(records, cells))
    failures = failure_lines(records, cells)
    md = ["# Benchmark report", "", summary, ""]
    if failures:
        md += ["Failed runs (no number reported for them):", ""] + failures + [""]
    md += ["Ratios compare medians over runs of the same cell; QuakeSpasm reports fps only "
           "(no start-up time; frame times only with --peer-tail).", ""]
    for name, title, _ in charts:
        md += ["![%s](images/%s)" % (title, name), ""]
    tails = tail_rows(records, cells)
    if tails:
        md += [TAIL_NOTE, "", markdown_table(TAIL_HEADER, tails), ""]
    rows = startup_rows(records, cells)
    if rows:
        md += ["Start-up to first frame (s):", "",
               markdown_table(["style", "runs", "median", "min–max"], rows), ""]
    quality = load_quality(directory)
    if quality:
        md += [QUALITY_NOTE, "", markdown_table(QUALITY_HEADER, quality_rows(quality)), ""]
    if pictures:
        md += ["Style gallery (the same demo frame in every style, one engine run):", ""]
        for caption, path in pictures:
            md += ["![%s](gallery/%s)" % (caption, os.path.basename(path))]
        md += [""]
    md += ["Machine:", "", markdown_table(["", ""], machine_rows(machine, records)), ""]
    with open(os.path.join(directory, "report.md"), "w") as f:
        f.write("\n".join(md))

    body = ["<h1>Benchmark report</h1>", html_table(SUMMARY_HEADER, summary_rows(records, cells))]
    if failures:
        body.append("<p>Failed runs (no number reported for them):</p><ul>%s</ul>" % "".join(
            "<li>%s</li>" % html.escape(line[2:]) for line in failures))
    body.append("<p>Ratios compare medians over runs of the same cell; QuakeSpasm reports fps "
                "only (no start-up time; frame times only with --peer-tail).</p>")
    for _, title, png in charts:
        body.append("<h2>%s</h2>%s" % (html.escape(title), img_tag(png, title)))
    if tails:
        body.append("<h2>Frame-time tail</h2><p>%s</p>%s" % (
            html.escape(TAIL_NOTE), html_table(TAIL_HEADER, tails)))
    if rows:
        body.append(html_table(["style", "runs", "median s", "min–max s"], rows))
    if quality:
        body.append("<h2>Line quality</h2><p>%s</p>%s" % (
            html.escape(QUALITY_NOTE), html_table(QUALITY_HEADER, quality_rows(quality))))
    if pictures:
        body.append("<h2>Style gallery</h2><p>The same demo frame in every style, taken in one "
                    "engine run.</p>")
        for caption, path in pictures:
            with open(path, "rb") as f:
                body.append("<figure>%s<figcaption>%s</figcaption></figure>" % (
                    img_tag(f.read(), caption), html.escape(caption)))
    body.append("<h2>Machine</h2>" + html_table(["", ""], machine_rows(machine, records)))
    style = ("body{font-family:sans-serif;max-width:1200px;margin:auto}"
             "table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:2px 6px}"
             "figure{display:inline-block;margin:4px}")
    page = ("<!DOCTYPE html><html><head><meta charset='utf-8'><title>nprquake benchmark</title>"
            "<style>%s</style></head><body>%s</body></html>\n" % (style, "\n".join(body)))
    with open(os.path.join(directory, "report.html"), "w") as f:
        f.write(page)
    print("bench_report.py: %s/report.html, report.md, charts in %s" % (directory, images))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("directory")
    parser.add_argument("--summary-only", action="store_true")
    parser.add_argument("--gallery")
    parser.add_argument("--machine")
    parser.add_argument("--images")
    args = parser.parse_args()
    records = load_records(args.directory)
    if not records:
        sys.exit("bench_report.py: no runs in %s/results.jsonl" % args.directory)
    cells = collect(records)
    write_summary(args.directory, records, cells)
    if args.summary_only:
        return
    machine = {}
    if args.machine:
        with open(args.machine) as f:
            machine = json.load(f)
    write_report(args.directory, records, cells, args.gallery, machine,
                 args.images or os.path.join(args.directory, "images"))


if __name__ == "__main__":
    main()
