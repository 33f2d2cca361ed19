#!/usr/bin/env python3
"""The cost table of demos/bench_obscurance.sh: from its cost.tsv (one row per run), the median
over the rounds of each resolution and config, as a markdown table: fps and its ratio to the
run without obscurance, the pass's GPU time per frame in all and per stage, and the ratio of the
whole pass and of the estimate alone to points12's."""
import statistics
import sys

STAGES = ("obscurance_ms", "moments_ms", "estimate_ms", "blur_ms", "composite_ms")


def number(text):
    try:
        return float(text)
    except ValueError:
        return None


def medians(path):
    """{(resolution, config): {column: median or None}}, in the order rows first appear."""
    with open(path, encoding="utf-8") as f:
        header = f.readline().rstrip("\n").split("\t")
        runs = {}
        for line in f:
            row = dict(zip(header, line.rstrip("\n").split("\t")))
            runs.setdefault((row["resolution"], row["config"]), []).append(row)
    table = {}
    for key, rows in runs.items():
        cell = {"runs": len(rows)}
        for column in ("fps",) + STAGES:
            values = [v for v in (number(r.get(column, "")) for r in rows) if v is not None]
            cell[column] = statistics.median(values) if values else None
        table[key] = cell
    return table


def ratio(a, b):
    return f"{a / b:.2f}" if a is not None and b else "—"


def figure(value, digits):
    return "failed" if value is None else f"{value:.{digits}f}"


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: obscurance_cost.py cost.tsv")
    table = medians(sys.argv[1])
    print("| resolution | config | runs | fps | x off | pass ms | moments | estimate | blur "
          "| composite | pass x points12 | estimate x points12 |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for (resolution, config), cell in table.items():
        off = table.get((resolution, "off"), {})
        points = table.get((resolution, "points12"), {})
        stages = [figure(cell[s], 4) for s in STAGES[1:]]
        if config == "off":
            print(f"| {resolution} | off | {cell['runs']} | {figure(cell['fps'], 1)} | 1 "
                  "| — | — | — | — | — | — | — |")
            continue
        print(f"| {resolution} | {config} | {cell['runs']} | {figure(cell['fps'], 1)} "
              f"| {ratio(cell['fps'], off.get('fps'))} | {figure(cell['obscurance_ms'], 4)} "
              f"| {' | '.join(stages)} "
              f"| {ratio(cell['obscurance_ms'], points.get('obscurance_ms'))} "
              f"| {ratio(cell['estimate_ms'], points.get('estimate_ms'))} |")


if __name__ == "__main__":
    main()
