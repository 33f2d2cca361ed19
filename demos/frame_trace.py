#!/usr/bin/python3
"""Explains a -benchtrace file: where the slow frames' time went.

usage: frame_trace.py TRACE.tsv [--png OUT.png] [--slow X]

For every timedemo in the file: the frame-time percentiles, then each stage's median and
99th-percentile CPU time and its share of the frames slower than X times the median (default
2.5: the tail the benchmark targets). Those slow frames' own stage times show what made them
slow. With --png, a chart per timedemo: the frame times stacked by stage, over the run.
"""
import argparse
import sys


def read_sections(path):
    """[(header, columns, rows)] with rows as lists of floats (None for empty GPU cells)."""
    sections = []
    with open(path) as f:
        header = None
        columns = None
        for line in f:
            line = line.rstrip("\n")
            if line.startswith("# trace full"):
                print(line, file=sys.stderr)
            elif line.startswith("# "):
                header, columns = line[2:], None
                sections.append([header, None, []])
            elif columns is None and sections:
                columns = line.split("\t")
                sections[-1][1] = columns
            elif sections:
                sections[-1][2].append([float(v) if v else None for v in line.split("\t")])
    return [tuple(s) for s in sections if s[1]]


def percentile(sorted_values, p):
    if not sorted_values:
        return 0.0
    i = min(len(sorted_values) - 1, int(p / 100.0 * len(sorted_values)))
    return sorted_values[i]


def describe(header, columns, rows, slow_factor):
    total = columns.index("total_ms")
    stages = [i for i, c in enumerate(columns) if c.endswith("_ms") and c != "total_ms"
              and not c.startswith("gpu_")]
    gpu = [i for i, c in enumerate(columns) if c.startswith("gpu_")]
    times = sorted(r[total] for r in rows)
    median = percentile(times, 50)
    slow = [r for r in rows if r[total] > slow_factor * median]
    low1 = times[-max(1, len(times) // 100):]
    print(f"== {header}")
    print(f"frames {len(rows)}  median {median:.2f} ms  95th {percentile(times, 95):.2f}  "
          f"99th {percentile(times, 99):.2f}  max {times[-1]:.2f}  "
          f"99th/median {percentile(times, 99) / median:.2f}  "
          f"1% low/avg fps {(sum(times) / len(times)) / (sum(low1) / len(low1)):.2f}")
    print(f"{len(slow)} frames over {slow_factor}x the median ({slow_factor * median:.1f} ms)")
    print(f"{'stage':<22}{'median':>9}{'99th':>9}{'max':>9}{'in slow frames':>16}")
    slow_sum = sum(r[total] for r in slow) or 1.0
    for i in stages + gpu:
        values = sorted(r[i] for r in rows if r[i] is not None)
        if not values or values[-1] < 0.05:
            continue
        share = sum(r[i] or 0.0 for r in slow) / slow_sum
        note = "" if i in stages else "  (GPU, not in total)"
        print(f"{columns[i][:-3]:<22}{percentile(values, 50):9.2f}{percentile(values, 99):9.2f}"
              f"{values[-1]:9.2f}{share * 100:15.0f}%{note}")
    worst = sorted(range(len(rows)), key=lambda k: rows[k][total])[-5:][::-1]
    for k in worst:
        r = rows[k]
        top = sorted(stages, key=lambda i: r[i], reverse=True)[:3]
        parts = ", ".join(f"{columns[i][:-3]} {r[i]:.1f}" for i in top)
        print(f"  frame {int(r[0])}: {r[total]:.1f} ms ({parts}); "
              f"{int(r[-3])} entities, {int(r[-2])} dlights, {int(r[-1])} particles")


def plot(sections, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(len(sections), 1, figsize=(10, 3.2 * len(sections)), squeeze=False)
    for ax, (header, columns, rows) in zip(axes[:, 0], sections):
        stages = [i for i, c in enumerate(columns) if c.endswith("_ms") and c != "total_ms"
                  and not c.startswith("gpu_")]
        shown = [i for i in stages if max(r[i] for r in rows) >= 0.5]
        frames = [r[0] for r in rows]
        ax.stackplot(frames, [[r[i] for r in rows] for i in shown],
                     labels=[columns[i][:-3] for i in shown], linewidth=0)
        ax.set_title(header, fontsize=9)
        ax.set_xlabel("frame")
        ax.set_ylabel("ms")
        ax.legend(loc="upper right", fontsize=7, ncol=4)
    fig.tight_layout()
    fig.savefig(out, dpi=80)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("trace")
    parser.add_argument("--png", help="write a chart of the stages over the run")
    parser.add_argument("--slow", type=float, default=2.5, help="slow frame: X times the median")
    args = parser.parse_args()
    sections = read_sections(args.trace)
    if not sections:
        sys.exit(f"frame_trace.py: {args.trace}: no timedemo in the file")
    for header, columns, rows in sections:
        if rows:
            describe(header, columns, rows, args.slow)
    if args.png:
        plot([s for s in sections if s[2]], args.png)


if __name__ == "__main__":
    main()
