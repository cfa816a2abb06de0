"""A strided sample of the paper preset's sweeps as specs that `corlab reproduce --studies` runs.

Every K-th case of each sweep (in its `corlab sweep --dry-run` order) written as explicit
`[[cases]]` under the study's own [study] and [base], so that the sample's case ids are the full
study's and `tests/regression/sweep_compare.py` joins its results.csv with a full or sampled run's
(issue 43: measuring the reproduction side by side when a full run does not fit).
    python3 scripts/paper_sample_specs.py CORLAB_BIN OUT_DIR
writes OUT_DIR/paper/{table2,yield_velocity,alumina,table4}.toml; then
    corlab reproduce --studies OUT_DIR --only table2 yield_velocity alumina table4 --no-report \\
        --out DIR"""
# SPDX-License-Identifier: BSD-3-Clause
import os
import re
import subprocess
import sys

# (study, its runs, the stride): 21 + 22 + 5 + 5 = 53 of the 453 runs, every speed of each study.
SAMPLE = (("table2", 165, 8), ("yield_velocity", 240, 11), ("alumina", 24, 5), ("table4", 24, 5))
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def toml_value(text):
    try:
        return repr(float(text))
    except ValueError:
        return f'"{text}"'


def main(argv):
    if len(argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    binary, out = argv
    os.makedirs(os.path.join(out, "paper"), exist_ok=True)
    for name, runs, stride in SAMPLE:
        src = os.path.join(ROOT, "studies", "paper", f"{name}.toml")
        with open(src) as f:
            head = re.split(r"^\[\[cases\]\]|^\[grid\]", f.read(), flags=re.M)[0]
        rows = subprocess.run([binary, "sweep", src, "--dry-run"], capture_output=True, text=True,
                              check=True).stdout.splitlines()
        if len(rows) != runs + 1:
            print(f"{name}: {len(rows) - 1} runs, expected {runs}", file=sys.stderr)
            return 1
        keys = rows[0].split()[1:]
        text = [head.rstrip() + "\n"]
        for i in range(0, runs, stride):
            text.append("\n[[cases]]\n")
            text += [f'"{k}" = {toml_value(v)}\n' for k, v in zip(keys, rows[1 + i].split()[1:])]
        with open(os.path.join(out, "paper", f"{name}.toml"), "w") as f:
            f.write("".join(text))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
