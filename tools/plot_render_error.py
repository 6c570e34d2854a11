#!/usr/bin/python3
"""Draws raylab-bench-render's render_error.csv: run time against image error.

    /usr/bin/python3 tools/plot_render_error.py RENDER_ERROR_CSV OUTPUT_PNG

One panel per scene: seconds to render (x, log) against the RMS error to the reference
(y, log; depth 16 at 1280x960), one line for the bounce-depth sweep (at 1280x960) and one
for the image-size sweep (at depth 5, resampled to 1280x960). An error of zero (the image
is the reference) is drawn on a dotted line at the bottom. Lower and further left is better.
Needs matplotlib (Debian: python3-matplotlib).
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

FLOOR = 1e-5  # where an error of zero is drawn


def main(csv_path, png_path):
    with open(csv_path, newline="") as f:
        rows = list(csv.DictReader(f))
    scenes = list(dict.fromkeys(r["scene"] for r in rows))
    fig, axes = plt.subplots(1, len(scenes), figsize=(6 * len(scenes), 4.5), squeeze=False)
    for ax, scene in zip(axes[0], scenes):
        for sweep, style, label in (("depth", "o-", "bounce depth (label) at 1280x960"),
                                    ("width", "s--", "image width (label) at depth 5")):
            points = [r for r in rows if r["scene"] == scene and r["sweep"] == sweep]
            xs = [float(r["seconds"]) for r in points]
            ys = [max(float(r["rms_error"]), FLOOR) for r in points]
            ax.plot(xs, ys, style, label=label)
            for r, x, y in zip(points, xs, ys):
                ax.annotate(r["setting"], (x, y), textcoords="offset points", xytext=(4, 4), fontsize=8)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.axhline(FLOOR, linestyle=":", color="grey")
        ax.text(0.01, FLOOR * 1.3, "error 0", color="grey", fontsize=8, transform=ax.get_yaxis_transform())
        ax.set_xlabel("seconds to render (one thread)")
        ax.set_ylabel("RMS error against the reference")
        ax.set_title(scene)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png_path, dpi=110)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
