#!/usr/bin/env python3
"""The layers of lib/ (README, "Layers"): what each folder's files may include of the project.

    core/          vibrofric/core/ only: templates on the number type, no text formats, no files
    api/           core and api
    verification/  core, api and verification
    tool/, python/ api, and verification/claims.hpp (the `verify` command): the front ends

Within core/, modules (lib/core/include/vibrofric/core/MODULE/ and lib/core/src/MODULE/, each with a
README.md stating its contract) include only the foundation (the headers directly in core/ and
core/detail/) and the modules below them:
    waves      foundation
    flat       waves
    curved     waves, flat
    dynamics   waves, flat, curved (the MDR row the rig's body carries)
    inplane    waves, flat, curved (the MDR row of in-plane springs)
    certified  foundation only
(lib/core/src/instances compiles the solvers once per number type and may include any of them.)

Two more rules keep the units small and the core free of text I/O:
    every file under lib/ has at most MAX_LINES lines;
    core/ includes no stream or stdio header (<fstream>, <sstream>, <iostream>, <istream>,
    <ostream>, <cstdio>) and parses no number text (strto*, std::sto*, ato*, from_chars, sscanf):
    it reads no files and no decimal text (the API's Decimal does, api/decimal_value.hpp).

Exit status 1 with one line per include that crosses a layer the wrong way (or per broken rule),
0 otherwise.
Usage: check.py [LIB_DIR]   (default: the lib/ folder next to tests/)
       check.py --self-test   (the check finds a planted violation of each kind)
"""
import pathlib
import re
import sys
import tempfile

ALLOWED = {
    "core": ("vibrofric/core/",),
    "api": ("vibrofric/core/", "vibrofric/api/"),
    "verification": ("vibrofric/core/", "vibrofric/api/", "vibrofric/verification/"),
    "tool": ("vibrofric/api/", "vibrofric/verification/claims.hpp"),
    "python": ("vibrofric/api/", "vibrofric/verification/claims.hpp"),
}
INCLUDE = re.compile(r'^\s*#\s*include\s*[<"](vibrofric/[^>"]+)[>"]')
MAX_LINES = 900
CORE_PARSING = re.compile(r'\b(strto[a-z]*|std::sto[a-z]+|ato[fil]|from_chars|sscanf)\s*\(')
MODULES = {
    "waves": (),
    "flat": ("waves",),
    "curved": ("waves", "flat"),
    "dynamics": ("waves", "flat", "curved"),
    "inplane": ("waves", "flat", "curved"),
    "certified": (),
}
CORE_INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]vibrofric/core/([^>"]+)[>"]')


def core_module(lib, path):
    """The core module of a file under lib/core/ ("" for the foundation, "instances" for src/instances)."""
    rel = path.relative_to(lib / "core").parts
    inner = rel[3:] if rel[:3] == ("include", "vibrofric", "core") else rel[1:] if rel[0] == "src" else ()
    if len(inner) > 1 and (inner[0] in MODULES or inner[0] == "instances"):
        return inner[0]
    return ""


def module_violations(lib):
    found = []
    core = lib / "core"
    for module in MODULES:
        if not (core / "include" / "vibrofric" / "core" / module / "README.md").is_file():
            found.append(f"{core}/include/vibrofric/core/{module}: no README.md (its contract)")
    for path in sorted(core.rglob("*")) if core.is_dir() else []:
        if path.suffix not in (".hpp", ".cpp", ".h") or not path.is_file():
            continue
        module = core_module(lib, path)
        if module == "instances":
            continue
        allowed = ("",) + MODULES.get(module, ()) + ((module,) if module else ())
        for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            m = CORE_INCLUDE.match(line)
            if not m:
                continue
            parts = m.group(1).split("/")
            target = parts[0] if len(parts) > 1 and parts[0] in MODULES else ""
            if target not in allowed:
                found.append(f"{path}:{number}: core module {module or 'foundation'} includes vibrofric/core/{m.group(1)} "
                             f"(it may include {', '.join(a or 'the foundation' for a in allowed)})")
    return found


CORE_FORBIDDEN = re.compile(r'^\s*#\s*include\s*<(fstream|sstream|iostream|istream|ostream|cstdio|stdio\.h)>')


def violations(lib):
    found = []
    for path in sorted(lib.rglob("*")):
        if path.suffix not in (".hpp", ".cpp", ".h") or not path.is_file():
            continue
        layer = path.relative_to(lib).parts[0]
        if layer not in ALLOWED:
            found.append(f"{path}: in no layer (expected under one of {', '.join(ALLOWED)})")
            continue
        # A header's own folder must match its layer: lib/core/include/vibrofric/core/...
        rel = path.relative_to(lib / layer).as_posix()
        if rel.startswith("include/") and not rel.startswith(f"include/vibrofric/{layer}/"):
            found.append(f"{path}: a {layer} header outside include/vibrofric/{layer}/")
        lines = path.read_text(encoding="utf-8").splitlines()
        if len(lines) > MAX_LINES:
            found.append(f"{path}: {len(lines)} lines (at most {MAX_LINES}: split it by concern)")
        for number, line in enumerate(lines, 1):
            if layer == "core" and (m := CORE_FORBIDDEN.match(line)):
                found.append(f"{path}:{number}: core includes <{m.group(1)}> (the core reads no files and "
                             "formats no text streams)")
            if layer == "core" and (m := CORE_PARSING.search(line.split("//")[0])):
                found.append(f"{path}:{number}: core parses number text ({m.group(1)}): decimal text is read "
                             "by the API (api/decimal_value.hpp)")
            m = INCLUDE.match(line)
            if m and not m.group(1).startswith(ALLOWED[layer]):
                found.append(f"{path}:{number}: {layer} includes {m.group(1)} "
                             f"(a {layer} file may include {', '.join(ALLOWED[layer])})")
    return found + module_violations(lib)


def self_test():
    with tempfile.TemporaryDirectory() as tmp:
        lib = pathlib.Path(tmp)
        files = {
            "core/include/vibrofric/core/a.hpp": '#include "vibrofric/api/evaluate.hpp"\n',
            "api/src/b.cpp": '#include "vibrofric/verification/envelope.hpp"\n',
            "tool/main.cpp": '#include "vibrofric/core/flat/solver.hpp"\n#include "vibrofric/verification/claims.hpp"\n',
            "core/include/vibrofric/api/c.hpp": "",
            "other/d.cpp": "",
            "core/src/e.cpp": "#include <sstream>\n",
            "core/src/h.cpp": "long f(const char* t) { return std::strtol(t, nullptr, 10); }  // strtod( in a comment\n",
            "api/src/f.cpp": "#include <sstream>\n" + "//\n" * 900,
            "api/src/g.cpp": "//\n" * 900,
            "core/include/vibrofric/core/waves/w.hpp": '#include "vibrofric/core/flat/solver.hpp"\n',
            "core/src/certified/c.cpp": '#include "vibrofric/core/numbers.hpp"\n',
            "core/src/instances/i.cpp": '#include "vibrofric/core/curved/curved.hpp"\n',
        }
        for name, text in files.items():
            (lib / name).parent.mkdir(parents=True, exist_ok=True)
            (lib / name).write_text(text)
        found = violations(lib)
    expected = ["a.hpp:1: core includes vibrofric/api/", "b.cpp:1: api includes vibrofric/verification/",
                "main.cpp:1: tool includes vibrofric/core/", "c.hpp: a core header outside", "d.cpp: in no layer",
                "e.cpp:1: core includes <sstream>", "f.cpp: 901 lines", "h.cpp:1: core parses number text (strtol)",
                "w.hpp:1: core module waves includes vibrofric/core/flat/solver.hpp"]
    expected += [f"core/{m}: no README.md" for m in MODULES]
    missing = [e for e in expected if not any(e in f for f in found)]
    if missing or len(found) != len(expected):
        print("self-test failed: expected", expected, "found", found)
        return 1
    print(f"self-test: {len(found)} planted violations found, the allowed includes (a module's foundation, "
          "the instances), a stream in the api and 900 lines pass")
    return 0


def main():
    if sys.argv[1:] == ["--self-test"]:
        return self_test()
    lib = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[2] / "lib"
    found = violations(lib)
    for line in found:
        print(line)
    if not found:
        print(f"layers: every include under {lib} stays in its layer and core module, no file over {MAX_LINES} lines, "
              "no stream or number parsing in core")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
