#!/usr/bin/python3
"""Draws raylab-bench-path's path_error.csv: the path tracer's error against time, per strategy.

    /usr/bin/python3 tools/plot_path_error.py PATH_ERROR_CSV OUTPUT_PNG

Left: CPU seconds of a one-thread render (x, log) against the RMS error to the converged
reference (y, log), one line per sampling strategy, each point labelled with its samples per
pixel. Right: the same errors against samples per pixel, with the slope -1/2 that an unbiased
estimator follows (error ~ 1 / sqrt(samples)). The dashed line is the error of GAMES101
assignment 7's 16-spp render (the games101 strategy at 16 spp, as raylab-bench-path takes it).
Lower and further left is better.
Needs matplotlib (Debian: python3-matplotlib).
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(csv_path, png_path):
    with open(csv_path, newline="") as f:
        rows = list(csv.DictReader(f))
    peer = [float(r["rmse"]) for r in rows if r["strategy"] == "games101" and r["spp"] == "16"]
    peer_rmse = peer[0] if peer else None
    strategies = list(dict.fromkeys(r["strategy"] for r in rows))
    fig, (time_axis, spp_axis) = plt.subplots(1, 2, figsize=(12, 4.8))
    for strategy in strategies:
        points = [r for r in rows if r["strategy"] == strategy]
        seconds = [float(r["seconds"]) for r in points]
        spp = [int(r["spp"]) for r in points]
        rmse = [float(r["rmse"]) for r in points]
        line, = time_axis.plot(seconds, rmse, "o-", label=strategy, markersize=4)
        for s, x, y in zip(spp, seconds, rmse):
            if s in (1, 16) or s == spp[-1]:
                time_axis.annotate(str(s), (x, y), textcoords="offset points", xytext=(3, 3), fontsize=7,
                                   color=line.get_color())
        spp_axis.plot(spp, rmse, "o-", label=strategy, markersize=4, color=line.get_color())
    # The slope of an unbiased estimator, through the first strategy's first point.
    first = [r for r in rows if r["strategy"] == strategies[0]]
    s0, e0 = int(first[0]["spp"]), float(first[0]["rmse"])
    s1 = int(first[-1]["spp"])
    spp_axis.plot([s0, s1], [e0, e0 * (s1 / s0) ** -0.5], ":", color="grey", label="slope -1/2")
    for axis in (time_axis, spp_axis):
        if peer_rmse:
            axis.axhline(peer_rmse, linestyle="--", color="black", linewidth=0.8)
            axis.text(0.01, peer_rmse * 0.88, "GAMES101 estimator, 16 spp", ha="left", va="top", fontsize=8,
                      transform=axis.get_yaxis_transform())
        axis.set_xscale("log")
        axis.set_yscale("log")
        axis.set_ylabel("RMS error against the converged reference")
        axis.grid(True, which="both", alpha=0.3)
    time_axis.set_xlabel("CPU seconds of the render (one thread)")
    spp_axis.set_xlabel("samples per pixel")
    time_axis.set_title("error against time (Cornell box)")
    spp_axis.set_title("error against samples")
    time_axis.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png_path, dpi=110)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
