#!/usr/bin/python3
"""Compare every analytic CoR model on the seed paper's validation pairs (Ma et al. 2023, Table 3).

Calls the built corlab CLI (`corlab predict --model all ...`) for an alumina sphere on the
aluminium alloy and on the steel substrate over 0.05-6 m/s, and writes into --out:
  model_comparison.csv   columns pair,model,velocity,e,k1,k2,v_y,status
  model_comparison.png   two panels (one per pair); unverified models dashed, "(unverified)"

Usage:
  /usr/bin/python3 scripts/model_comparison.py [CORLAB_BIN] --out DIR [--points N]
The CLI path is argv[1], else $CORLAB_BIN, else ./build/bin/corlab.
"""
# SPDX-License-Identifier: BSD-3-Clause
import argparse
import csv
import io
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

SPHERE = "alumina_ma2023"
PAIRS = [("aluminium_ma2023", "alumina sphere on aluminium alloy"),
         ("steel_jackson2010", "alumina sphere on steel")]
V_RANGE = (0.05, 6.0)


def run_cli(binary, substrate, points):
    cmd = [binary, "predict", "--model", "all", "--sphere", SPHERE, "--substrate", substrate,
           "--velocity", f"{V_RANGE[0]}:{V_RANGE[1]}:{points}", "--spacing", "lin",
           "--format", "csv"]
    proc = subprocess.run(cmd, capture_output=True, text=True, check=False)
    if proc.returncode != 0:
        sys.exit(f"model_comparison: {' '.join(cmd)} failed ({proc.returncode}): {proc.stderr}")
    for line in proc.stderr.splitlines():  # the CLI's unverified-model warnings
        print(line, file=sys.stderr)
    return list(csv.DictReader(io.StringIO(proc.stdout)))


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("binary", nargs="?", default=None, help="path of the corlab CLI")
    parser.add_argument("--out", required=True, help="output directory")
    parser.add_argument("--points", type=int, default=240, help="velocities per pair")
    args = parser.parse_args()
    binary = args.binary or os.environ.get("CORLAB_BIN") or "./build/bin/corlab"
    if not os.path.exists(binary):
        sys.exit(f"model_comparison: corlab CLI not found at '{binary}' "
                 "(pass it or set CORLAB_BIN)")
    os.makedirs(args.out, exist_ok=True)

    rows = []
    for substrate, _ in PAIRS:
        for row in run_cli(binary, substrate, args.points):
            rows.append({"pair": f"{SPHERE}/{substrate}", **row})
    csv_path = os.path.join(args.out, "model_comparison.csv")
    with open(csv_path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=["pair", "model", "velocity", "e", "k1", "k2", "v_y",
                                               "status"])
        writer.writeheader()
        for row in rows:
            writer.writerow({k: row[k] for k in writer.fieldnames})

    fig, axes = plt.subplots(1, 2, figsize=(13, 5.2), sharey=True)
    models = list(dict.fromkeys(r["model"] for r in rows))
    colors = {m: plt.cm.tab20(i / max(len(models) - 1, 1)) for i, m in enumerate(models)}
    for ax, (substrate, title) in zip(axes, PAIRS):
        pair = f"{SPHERE}/{substrate}"
        for model in models:
            sel = [r for r in rows if r["pair"] == pair and r["model"] == model]
            v = [float(r["velocity"]) for r in sel]
            e = [float(r["e"]) for r in sel]
            unverified = sel[0]["status"] == "unverified"
            ax.plot(v, e, linestyle="--" if unverified else "-", color=colors[model],
                    linewidth=1.6, label=model + (" (unverified)" if unverified else ""))
        ax.set_title(title)
        ax.set_xlabel("impact velocity v [m/s]")
        ax.set_xlim(*V_RANGE)
        ax.grid(True, alpha=0.3)
    axes[0].set_ylabel("coefficient of restitution e [-]")
    axes[1].legend(fontsize=8, loc="upper right")
    fig.suptitle("Analytic CoR models, alumina sphere (Ma et al. 2023, Table 3); "
                 "dashed = unverified")
    fig.tight_layout()
    png_path = os.path.join(args.out, "model_comparison.png")
    fig.savefig(png_path, dpi=130)
    print(f"wrote {csv_path} ({len(rows)} rows) and {png_path}")


if __name__ == "__main__":
    main()
