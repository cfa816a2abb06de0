"""The README: short, its set-up commands, links and code map real, its model scores those of the
dataset, and its reproduction numbers checkable against fit.json (scripts/readme_numbers.py; the
check against a coarse reproduction runs in test_report.py on the fit.json it already makes)."""
# SPDX-License-Identifier: BSD-3-Clause
import copy
import importlib.util
import pathlib
import re
import shlex
import subprocess

ROOT = pathlib.Path(__file__).resolve().parents[2]
README = (ROOT / "README.md").read_text()
SPEC = importlib.util.spec_from_file_location("readme_numbers",
                                              ROOT / "scripts" / "readme_numbers.py")
readme_numbers = importlib.util.module_from_spec(SPEC)
SPEC.loader.exec_module(readme_numbers)


def table_rows(text, header_start):
    """The body rows of the Markdown table whose header starts with `header_start` (cell lists)."""
    lines = text.splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith(header_start))
    rows = []
    for line in lines[start + 2:]:
        if not line.startswith("|"):
            break
        rows.append([c.strip() for c in line.strip().strip("|").split("|")])
    return rows


def test_readme_is_short_and_starts_with_the_two_set_up_commands():
    lines = README.splitlines()
    assert len(lines) <= 250
    assert lines[3].startswith("apt-get update && apt-get install -y make && make run ")
    assert lines[4].startswith("apt-get update && apt-get install -y make && make test ")
    assert "## Code map" in lines


def test_readme_links_exist():
    links = re.findall(r"\]\(([^)#]+)(?:#[^)]*)?\)", README)
    assert len(links) > 10
    missing = [link for link in links if not link.startswith("http") and not (ROOT / link).exists()]
    # docs/user/errors.md is written in parallel (issue 29); every other link must resolve now.
    assert [m for m in missing if m != "docs/user/errors.md"] == []


def code_map_files(cell):
    """The paths of a code-map cell (globs); a bare name is in the folder of the path before it."""
    out, folder = [], None
    for name in re.findall(r"`([^`]+)`", cell):
        name = name.replace("<name>", "*").replace("<area>", "*")
        path = name if "/" in name else f"{folder}/{name}"
        out.append(path.rstrip("/"))
        folder = path.rstrip("/") if name.endswith("/") else str(pathlib.PurePosixPath(path).parent)
    return out


def test_code_map_names_files_and_symbols_that_exist():
    rows = table_rows(README, "| concept | file | symbol |")
    assert len(rows) >= 15
    for concept, files, symbols in rows:
        texts = []
        for p in code_map_files(files):
            found = [f for f in ROOT.glob(p) if f.is_file()]
            found += [f for d in ROOT.glob(p) if d.is_dir() for f in d.rglob("*") if f.is_file()]
            assert found, f"code map, {concept}: no file {p}"
            texts += [f.read_text(errors="replace") for f in found]
        for symbol in re.findall(r"`([^`]+)`", symbols):
            name = re.split(r"::|\.", symbol.rstrip("*"))[-1]
            assert any(name in t for t in texts), f"code map, {concept}: {symbol} not in {files}"


def test_model_scores_are_the_datasets():
    """The short model table: every scored model once, its RMS over all cases of each dataset
    (the first number of the "all cases" cell of each model_scores.md, which the README links)."""
    def rms_by_model(path):
        rows = table_rows((ROOT / path).read_text(), "| model | all cases (n) |")
        return {row[0]: row[1].split(" / ")[0] for row in rows}
    flats = rms_by_model("data/fe_restitution/model_scores.md")
    pairs = rms_by_model("data/fe_restitution_pairs/model_scores.md")
    got = table_rows(README, "| model | use it for |")
    assert sorted(row[0] for row in got) == sorted(flats)
    assert {row[0]: (row[2], row[3]) for row in got} == {m: (flats[m], pairs[m]) for m in flats}
    for path in ("data/fe_restitution/model_scores.md",
                 "data/fe_restitution_pairs/model_scores.md"):
        assert f"]({path})" in README


def test_readme_lines_are_at_most_100_characters():
    long = [n for n, line in enumerate(README.splitlines(), 1) if len(line) > 100]
    assert long == [], f"README lines over 100 characters: {long}"


def test_readme_quotes_what_its_dem_export_prints(tmp_path, corlab_bin):
    """The quick start's `corlab dem` line, run as written: the max |de| line the README quotes
    is the one it prints."""
    block = README[README.index("```sh runnable"):]
    lines = block[:block.index("```\n", 3)].splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith("corlab dem "))
    command = lines[start].rstrip("\\ ")
    while lines[start].endswith("\\"):
        start += 1
        command += " " + lines[start].strip().rstrip("\\ ")
    args = shlex.split(command)[1:]
    done = subprocess.run([corlab_bin] + args, cwd=tmp_path, capture_output=True, text=True,
                          check=True)
    printed = re.search(r"max \|de\|: ([^;]+);", done.stdout + done.stderr)
    assert printed, done.stdout
    assert f"    max |de|: {printed.group(1)}\n" in README


def fake_paper_fit():
    """A paper-preset fit.json with the fields the README's numbers come from."""
    def value(v, lo, hi):
        return {"value": v, "ci_lower": lo, "ci_upper": hi}
    return {
        "preset": "paper",
        "paper": {"slope": 0.056, "alpha": 1.16, "beta": 0.253, "n": 4.5, "m": -3.5, "c": 0.05,
                  "K": 15.81},
        "verification": {"mesh": [{"h_min": 1e-3, "e": 0.55491},
                                  {"h_min": 0.25e-3, "e": 0.53487},
                                  {"h_min": 0.18e-3, "e": 0.53978}]},
        "fits": {
            "restitution_law": {"slope": value(0.055481, 0.05469, 0.05628),
                                "alpha": value(1.0944, 1.062, 1.126),
                                "beta": value(0.23891, 0.2327, 0.2451)},
            "yield_velocity_fe": {"n": value(4.083, 4.011, 4.153),
                                  "m": value(-3.1966, -3.234, -3.159),
                                  "c": value(0.1312, 0.129, 0.134),
                                  "K_fixed_exponents": value(22.93, 21.2, 24.8)},
            "discretisation_error": {"all": {"count": 453, "median": 0.00271, "max": 0.0201,
                                             "max_relative": 0.0386, "max_case": {"e": 0.5201}}},
            "model_error": {"e_paper": {"overall": {"runs": 453, "rms_relative_error": 0.117,
                                                    "largest_relative_error": -1.0}},
                            "e_ours": {"overall": {"runs": 453, "rms_relative_error": 0.092}}},
            "corlab2026_versus_eq19": {"cases": 165, "corlab2026_at_least_as_close": 86,
                                       "corlab2026": {"rms": 0.033}, "ma2023": {"rms": 0.068}}}}


def test_readme_numbers_renders_the_readme_lines():
    lines = readme_numbers.lines(fake_paper_fit())
    assert lines[0] == ("| slope s of ln k1 (eq. 9) | 0.05548 | [0.05469, 0.05628] | 0.056 | "
                        "−0.9 % | yes |")
    assert lines[4] == ("| m in b = c Ē*^m (eq. 17) | −3.197 | [−3.234, −3.159] | −3.5 | "
                        "−8.7 % | no |")
    assert lines[5] == "| c in Pa (eq. 17) | 0.131 | [0.129, 0.134] | 0.05 | ×2.6 | no |"
    assert lines[7] == ("h_min = 1, 0.25, 0.18 mm: e = 0.5549, 0.5349, 0.5398; "
                        "0.25 → 0.18 mm: +0.92 %")
    assert lines[8] == ("over 453 runs the median error bar is 0.0027, the largest 0.020 "
                        "(3.9 % of e = 0.520)")
    assert lines[9].startswith("eq. 19 with the paper's constants against our 453 runs: "
                               "RMS 11.7 %, largest 100 %;")
    partial = copy.deepcopy(fake_paper_fit())
    del partial["fits"]["yield_velocity_fe"]
    assert readme_numbers.lines(partial)[3:7] == [None] * 4


def test_readme_check_finds_each_changed_number():
    fit = fake_paper_fit()
    text = "\n".join(["| coefficient | ours |", "|---|---|"] + readme_numbers.lines(fit))
    assert readme_numbers.check(fit, text) == []
    changed = text.replace("0.05548", "0.05549")
    assert len(readme_numbers.check(fit, changed)) == 1
    # a wrong paper constant is found for any preset; our values only for the paper preset
    coarse = dict(fit, preset="coarse")
    assert readme_numbers.check(coarse, changed) == []
    wrong_paper = text.replace("| 0.056 |", "| 0.057 |")
    assert len(readme_numbers.check(coarse, wrong_paper)) == 1


def test_readme_names_the_command_for_its_reproduction_numbers():
    assert "scripts/readme_numbers.py out/report/fit.json --check README.md" in README
    cells = readme_numbers.table_paper_cells(README)
    assert set(cells) == {row[0] for row in readme_numbers.REFIT_ROWS}
