"""scripts/lint/spdx_headers.py: where the SPDX line goes in each comment syntax, that --fix is
idempotent and leaves data alone (the tree itself is checked by `make lint-spdx`)."""
# SPDX-License-Identifier: BSD-3-Clause
import importlib.util
import pathlib

ROOT = pathlib.Path(__file__).resolve().parents[2]
SPEC = importlib.util.spec_from_file_location("spdx_headers",
                                              ROOT / "scripts" / "lint" / "spdx_headers.py")
spdx = importlib.util.module_from_spec(SPEC)
SPEC.loader.exec_module(spdx)
CPP = "// SPDX-License-Identifier: BSD-3-Clause\n"
HASH = "# SPDX-License-Identifier: BSD-3-Clause\n"


def test_the_line_follows_the_opening_description():
    text = "// one.cpp: what it is,\n// on two lines.\n#include <x>\n"
    assert spdx.with_header("src/one.cpp", text) == (
        "// one.cpp: what it is,\n// on two lines.\n" + CPP + "#include <x>\n")
    script = "#!/usr/bin/env bash\n# what it does\nset -e\n"
    assert spdx.with_header("a.sh", script) == "#!/usr/bin/env bash\n# what it does\n" + HASH + \
        "set -e\n"
    module = '#!/usr/bin/env python3\n"""What it is.\n\nMore.\n"""\nimport os\n'
    assert spdx.with_header("a.py", module) == (
        '#!/usr/bin/env python3\n"""What it is.\n\nMore.\n"""\n' + HASH + "import os\n")
    header = "/* c.h: the C API.\n * more\n */\n#ifndef C_H\n"
    assert spdx.with_header("c.h", header) == (
        "/* c.h: the C API.\n * more\n */\n/* SPDX-License-Identifier: BSD-3-Clause */\n"
        "#ifndef C_H\n")
    page = "<!DOCTYPE html>\n<!-- the page,\n     two lines -->\n<html>\n"
    assert spdx.with_header("p.html", page) == (
        "<!DOCTYPE html>\n<!-- the page,\n     two lines -->\n"
        "<!-- SPDX-License-Identifier: BSD-3-Clause -->\n<html>\n")


def test_a_file_without_a_description_gets_the_line_first():
    assert spdx.with_header("a.pc.in", "prefix=/usr\n") == HASH + "prefix=/usr\n"
    assert spdx.with_header("b.toml", "[study]\n") == HASH + "[study]\n"
    assert spdx.with_header("c.hpp", "#pragma once\n") == CPP + "#pragma once\n"


def test_fix_is_idempotent_and_data_is_left_alone():
    once = spdx.with_header("src/one.cpp", "// one.cpp\nint x;\n")
    assert spdx.with_header("src/one.cpp", once) == once
    assert spdx.with_header("data/x.csv", "a,b\n") == "a,b\n"
    assert spdx.comment_syntax("tests/fuzz/corpus/config_toml/a.toml") is None
    assert spdx.comment_syntax("packaging/debian/postinst") == "#"


def test_another_licence_is_reported():
    assert spdx.licence_of(["// SPDX-License-Identifier: MIT"]) == "MIT"
    assert spdx.licence_of(["/* SPDX-License-Identifier: BSD-3-Clause */"]) == "BSD-3-Clause"
    assert spdx.licence_of(["<!-- SPDX-License-Identifier: BSD-3-Clause -->"]) == "BSD-3-Clause"
