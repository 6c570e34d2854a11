#!/usr/bin/python3
"""Draws raylab-bench-kernels' table: run time against error for each intersection kernel.

    /usr/bin/python3 tools/plot_kernels.py KERNELS_CSV OUTPUT_PNG

Three panels, each with nanoseconds per test on x: the relative error of t on the
adversarial inputs (log scale; the 99.9th percentile filled, the maximum open, joined by a
line); wrong hit/miss decisions per million where the exact answer is clear; and leaks per
million (rays through closed meshes for triangle tests, boxes holding a hit rejected for box
tests). Counts of zero are drawn on a dotted line at the bottom.
Lower and further left is better. Needs matplotlib (Debian: python3-matplotlib).
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

COLOURS = {"sphere": "tab:blue", "triangle": "tab:red", "box": "tab:green"}
MARKERS = ["o", "s", "^", "D"]


FLOOR = 0.5  # where a count of zero is drawn on the log-scale count panels


def main(csv_path, png_path):
    with open(csv_path, newline="") as f:
        rows = list(csv.DictReader(f))
    fig, (errors, wrong, leaks) = plt.subplots(1, 3, figsize=(16, 5.6))
    seen = {}
    zeros = {}  # labels already on the zero line of each panel: stack the next one above them
    for index, row in enumerate(rows):
        group = row["group"]
        marker = MARKERS[seen.setdefault(group, 0) % len(MARKERS)]
        seen[group] += 1
        colour = COLOURS.get(group, "black")
        ns = float(row["ns_per_test"])
        name = row["algorithm"]
        # Alternate the labels above and below their points so that neighbours stay legible.
        offset = (8, 5) if index % 2 == 0 else (8, -13)
        p999 = max(float(row["p999_relative_error"]), 1e-9)
        worst = max(float(row["max_relative_error"]), 1e-9)
        errors.plot([ns, ns], [p999, worst], color=colour, linewidth=1, alpha=0.6)
        errors.scatter([ns], [p999], color=colour, marker=marker, s=70, zorder=3,
                       label=f'{name} ({row["note"]})')
        errors.scatter([ns], [worst], facecolors="none", edgecolors=colour, marker=marker, s=70, zorder=3)
        errors.annotate(name, (ns, p999), textcoords="offset points", xytext=offset, fontsize=8)
        for axes, column in ((wrong, "wrong_decisions_per_million"), (leaks, "leaks_per_million")):
            if not row[column]:
                continue
            value = float(row[column])
            label_offset = offset
            if value == 0:
                stacked = zeros.setdefault(column, 0)
                zeros[column] += 1
                label_offset = (8, 5 + 11 * stacked)
            axes.scatter([ns], [max(value, FLOOR)], color=colour, marker=marker, s=70, zorder=3)
            axes.annotate(f"{name}: {value:.0f}", (ns, max(value, FLOOR)), textcoords="offset points",
                          xytext=label_offset, fontsize=8)
    errors.set_yscale("log")
    errors.set_ylabel("relative error of t against long double\n(filled: 99.9th percentile, open: max)")
    errors.set_title("error of t on adversarial inputs")
    wrong.set_ylabel("per million adversarial inputs")
    wrong.set_title("wrong hit/miss decisions where the answer is clear")
    leaks.set_ylabel("per million: rays through closed meshes (triangles),\nboxes holding a hit rejected (boxes)")
    leaks.set_title("leaks")
    for axes in (wrong, leaks):
        axes.set_yscale("log")
        axes.set_ylim(FLOOR * 0.5, 1e6)
        axes.axhline(FLOOR, color="grey", linewidth=0.8, linestyle=":")
        axes.text(0.98, 0.97, "dotted line: zero", transform=axes.transAxes, fontsize=8, color="grey", ha="right", va="top")
    for axes in (errors, wrong, leaks):
        axes.set_xlabel("nanoseconds per test (one thread, ordinary inputs)")
        axes.grid(True, which="both", alpha=0.3)
        low, high = axes.get_xlim()
        axes.set_xlim(low, high + 0.25 * (high - low))  # room for the labels on the right
    fig.legend(*errors.get_legend_handles_labels(), loc="lower center", ncol=4, fontsize=8, frameon=False)
    fig.suptitle("raylab-bench-kernels: run time against error (lower and further left is better)")
    fig.tight_layout(rect=(0, 0.09, 1, 0.96))
    fig.savefig(png_path, dpi=110)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
