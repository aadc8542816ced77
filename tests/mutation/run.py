#!/usr/bin/env python3
"""Mutation testing of lib/: apply each mutant of tests/mutation/patches to a clean copy of the
committed tree, rebuild incrementally, run ctest, and record whether the suite kills it.

    tests/mutation/run.py                      # every mutant of the index (hours on 2 cores)
    tests/mutation/run.py --only m03-events-wrap-shift,m17-rounding-test-one-sided
    tests/mutation/run.py --smoke              # the two smoke mutants (ctest: mutation.smoke)

The copy is HEAD of this repository (`git archive`), in WORK/src with its build in WORK/build
(default WORK = build/mutation): -O1, no benchmarks. A later run at another commit updates only
the files that changed, so the build stays incremental. Per mutant: patch, build, ctest (the
release preset's selection: everything but label `slow`), patch -R. A mutant is

  killed          some test failed or timed out (listed, with the time),
  survived        every test passed,
  does-not-build  the build failed (not counted in the score),
  equivalent      survived, and the index's equivalence list argues no input changes any output.

The unmutated tree must build and pass first (the baseline); its slowest test sets the per-test
timeout. Every run appends to WORK/results.jsonl (its baseline, then one line per mutant as it
finishes); after each mutant tests/mutation/results/latest.json and latest.md (the report's
mutation section) are rewritten from it: each mutant's latest record, with the commit it was run
at, so a rerun of some mutants (--only, after a test was added for a survivor) replaces theirs.
"""
import argparse
import datetime
import filecmp
import json
import os
import re
import shutil
import subprocess
import sys
import tarfile
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
INDEX = os.path.join(HERE, "README.md")
PATCHES = os.path.join(HERE, "patches")
RESULTS = os.path.join(HERE, "results")

# The smoke mutants: in the root finders, killed by test_roots, which is header-only, so the smoke
# run builds one small program instead of the library (it runs inside the CI's 30 minutes).
SMOKE = ["m18-root-tolerance-half", "m45-polished-root-sign-unchecked"]
SMOKE_TARGETS = ["test_roots"]
SMOKE_TESTS = "^Roots\\."

# Stage 1 of a mutant: the library, the tool and the core test programs, and their tests (a third
# of the build). Most mutants die here; one that survives is built in full and put through the
# whole selection, so the verdict is the whole suite's either way.
STAGE1_TARGETS = ["vibrofric-tool", "test_roots", "test_solver", "test_events", "test_waveforms", "test_claims", "test_curved",
                  "test_spring_row"]
STAGE1_TOOL_TESTS = ("tool.", "verification.mpmath")


def fail(msg):
    print("run.py: " + msg, file=sys.stderr)
    sys.exit(2)


def read_index():
    """Rows `| id | area | what it breaks | regime |` of the mutant table, and the equivalence
    arguments `- id: why` under the heading "Equivalent mutants"."""
    rows, equivalent, section = [], {}, ""
    for line in open(INDEX, encoding="utf-8"):
        if line.startswith("#"):
            section = line.strip("# \n").lower()
            continue
        m = re.match(r"\|\s*(m\d{2,3}-[a-z0-9-]+)\s*\|\s*([a-z-]+)\s*\|(.*)\|(.*)\|\s*$", line)
        if m and section.startswith("mutants"):
            rows.append({"id": m.group(1), "area": m.group(2), "breaks": m.group(3).strip(),
                         "regime": m.group(4).strip()})
        m = re.match(r"-\s*`?(m\d{2,3}-[a-z0-9-]+)`?:\s*(.*)", line)
        if m and section.startswith("equivalent"):
            equivalent[m.group(1)] = m.group(2).strip()
    ids = [r["id"] for r in rows]
    if len(set(ids)) != len(ids):
        fail("the index lists a mutant twice")
    files = sorted(f[:-6] for f in os.listdir(PATCHES) if f.endswith(".patch"))
    if sorted(ids) != files:
        fail("index and patches differ: only in the index %s, only as patches %s" %
             (sorted(set(ids) - set(files)), sorted(set(files) - set(ids))))
    for e in equivalent:
        if e not in ids:
            fail("equivalence argued for unknown mutant " + e)
    return rows, equivalent


def sh(cmd, cwd=None, timeout=None, log=None):
    t0 = time.time()
    try:
        p = subprocess.run(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                           timeout=timeout)
        code, out = p.returncode, p.stdout
    except subprocess.TimeoutExpired as e:
        code, out = "timeout", (e.stdout or b"").decode(errors="replace") if isinstance(e.stdout, bytes) else (e.stdout or "")
    if log:
        with open(log, "a") as f:
            f.write("$ %s\n%s\n" % (" ".join(cmd), out))
    return code, out, time.time() - t0


def sync_copy(src_dir):
    """WORK/src := HEAD, rewriting only files whose content changed (keeps the build incremental)."""
    commit = subprocess.check_output(["git", "rev-parse", "HEAD"], cwd=ROOT, text=True).strip()
    dirty = subprocess.run(["git", "diff", "--quiet", "HEAD", "--", "lib", "tests", "CMakeLists.txt"],
                           cwd=ROOT).returncode != 0
    with tempfile.TemporaryDirectory() as tmp:
        tar = os.path.join(tmp, "head.tar")
        subprocess.check_call(["git", "archive", "-o", tar, "HEAD"], cwd=ROOT)
        fresh = os.path.join(tmp, "tree")
        with tarfile.open(tar) as t:
            t.extractall(fresh)
        os.makedirs(src_dir, exist_ok=True)
        for base, dirs, files in os.walk(fresh):
            rel = os.path.relpath(base, fresh)
            os.makedirs(os.path.join(src_dir, rel), exist_ok=True)
            for f in files:
                a, b = os.path.join(base, f), os.path.join(src_dir, rel, f)
                if not os.path.exists(b) or not filecmp.cmp(a, b, shallow=False):
                    shutil.copy2(a, b)
                    os.utime(b)  # newer than any object built from the old content
        for base, dirs, files in os.walk(src_dir):
            rel = os.path.relpath(base, src_dir)
            for f in files:
                if not os.path.exists(os.path.join(fresh, rel, f)):
                    os.remove(os.path.join(base, f))
    return commit, dirty


def failed_tests(build):
    path = os.path.join(build, "Testing", "Temporary", "LastTestsFailed.log")
    if not os.path.exists(path):
        return []
    return [line.strip().split(":", 1)[1] for line in open(path) if ":" in line]


def first_failure(output):
    m = re.search(r"Test\s+#\d+: (\S+) \.+\*\*\*(?:Failed|Timeout|Exception)", output)
    return [m.group(1)] if m else []


def test_times(output):
    """name -> seconds, from ctest's progress lines."""
    times = {}
    for m in re.finditer(r"Test\s+#\d+: (\S+) \.+.*?([\d.]+) sec", output):
        times[m.group(1)] = float(m.group(2))
    return times


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--work", default=os.path.join(ROOT, "build", "mutation"))
    ap.add_argument("--only", default="", help="comma-separated mutant ids")
    ap.add_argument("--smoke", action="store_true", help="the two smoke mutants, the tool only")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--stop-on-failure", action="store_true",
                    help="stop a mutant's ctest at its first failing test (faster; lists one killer)")
    ap.add_argument("--check-patches", action="store_true",
                    help="only check that every mutant applies to this tree (patch --dry-run), then exit")
    a = ap.parse_args()

    rows, equivalent = read_index()
    if a.check_patches:
        stale = []
        for r in rows:
            code, out, _ = sh(["patch", "-p1", "--dry-run", "-s", "-N", "-i",
                               os.path.join(PATCHES, r["id"] + ".patch")], cwd=ROOT)
            if code != 0:
                why = [l for l in out.splitlines() if "FAILED" in l or "can't find" in l]
                stale.append("%s: does not apply (%s)" % (r["id"], why[0].strip() if why else "patch --dry-run failed"))
        for line in stale:
            print("stale mutant " + line)
        print("%d of %d mutants apply to %s" % (len(rows) - len(stale), len(rows), ROOT))
        sys.exit(1 if stale else 0)
    by_id = {r["id"]: r for r in rows}
    chosen = list(SMOKE) if a.smoke else ([s for s in a.only.split(",") if s] or [r["id"] for r in rows])
    for c in chosen:
        if c not in by_id:
            fail("unknown mutant '%s': expected an id of %s" % (c, os.path.relpath(INDEX, ROOT)))

    def patched_file(mid):
        for line in open(os.path.join(PATCHES, mid + ".patch")):
            if line.startswith("+++ "):
                return line.split()[1]
        return ""
    # Mutants of one .cpp rebuild in seconds, of a header in minutes: the cheap ones first.
    chosen.sort(key=lambda mid: (not patched_file(mid).endswith(".cpp"), [r["id"] for r in rows].index(mid)))

    work = os.path.abspath(a.work)
    src, build = os.path.join(work, "src"), os.path.join(work, "build")
    os.makedirs(work, exist_ok=True)
    log = os.path.join(work, "run.log")
    open(log, "w").close()
    commit, dirty = sync_copy(src)
    started = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    print("mutation run at %s%s, %d mutant(s), work %s" % (commit[:12], " (lib/tests differ from HEAD: "
          "the run tests HEAD)" if dirty else "", len(chosen), work), flush=True)

    # The smoke run builds at -O0 (one small program: compile time is all it costs); the full run
    # keeps -O1.
    configure = ["cmake", "-S", src, "-B", build, "-DCMAKE_BUILD_TYPE=Release",
                 "-DCMAKE_CXX_FLAGS_RELEASE=%s -DNDEBUG" % ("-O0" if a.smoke else "-O1"),
                 "-DVIBROFRIC_BUILD_BENCHMARKS=OFF"]
    if a.smoke:
        configure += ["-DVIBROFRIC_BUILD_PROOFS=OFF", "-DVIBROFRIC_PYTHON=OFF"]
    code, out, _ = sh(configure, log=log)
    if code != 0:
        fail("configure failed (see %s)" % log)
    build_cmd = ["cmake", "--build", build, "-j", str(a.jobs)]
    if a.smoke:
        build_cmd += ["--target"] + SMOKE_TARGETS
    ctest = ["ctest", "--test-dir", build, "-j", str(a.jobs), "-LE", "^(slow|mutation)$"]
    if a.smoke:
        ctest += ["-R", SMOKE_TESTS]

    # Baseline: the unmutated copy builds and passes, and gives each test's time.
    code, out, t_build = sh(build_cmd, log=log)
    if code != 0:
        fail("the unmutated tree does not build (see %s)" % log)
    code, out, t_test = sh(ctest + ["--timeout", "1800"], log=log)
    if code != 0:
        fail("the unmutated tree fails its tests: %s (see %s)" % (", ".join(failed_tests(build)), log))
    base_times = test_times(out)
    if not base_times:
        fail("the selection runs no tests (see %s)" % log)
    timeout = max(120, int(5 * max(base_times.values() or [60])))
    print("baseline: build %.0f s, %d tests pass in %.0f s; per-test timeout %d s" %
          (t_build, len(base_times), t_test, timeout), flush=True)

    results_path = os.path.join(work, "results.jsonl")
    with open(results_path, "a") as f:
        f.write(json.dumps({"type": "run", "commit": commit, "dirty": dirty, "started": started,
                            "baseline": {"build_s": round(t_build), "test_s": round(t_test), "tests": len(base_times)},
                            "stop_on_failure": a.stop_on_failure, "staged": not a.smoke}) + "\n")
    stage1 = [] if a.smoke else stage1_tests(build)
    results = []
    for k, mid in enumerate(chosen):
        patch = os.path.join(PATCHES, mid + ".patch")
        r = dict(by_id[mid], build_s=0.0, test_s=0.0, killed_by=[], timed_out=[])
        code, out, _ = sh(["patch", "-p1", "-s", "-N", "-i", patch], cwd=src, log=log)
        if code != 0:
            fail("%s does not apply to %s: %s" % (mid, commit[:12], out.strip()))
        try:
            stages = [(build_cmd + ["--target"] + STAGE1_TARGETS, ctest + ["-R", "^(%s)$" % "|".join(map(re.escape, stage1))])] \
                if stage1 else []
            stages.append((build_cmd, ctest))
            for b, c in stages:
                code, out, dt = sh(b, timeout=3600, log=log)
                r["build_s"] += dt
                if code != 0:
                    r["status"] = "does-not-build"
                    break
                cmd = c + ["--timeout", str(timeout)] + (["--stop-on-failure"] if a.stop_on_failure else [])
                code, out, dt = sh(cmd, timeout=4 * 3600, log=log)
                r["test_s"] += dt
                killers = failed_tests(build) if code != 0 else []
                if a.stop_on_failure and killers:
                    # ctest interrupts the tests still running at the first failure and lists them
                    # as failed too: only the first to fail in completion order is a killer.
                    killers = first_failure(out) or killers[:1]
                if code != 0 and not killers:
                    killers = ["(ctest: %s)" % code]
                r["killed_by"] = killers
                r["timed_out"] = re.findall(r"Test\s+#\d+: (\S+) \.+\*\*\*Timeout", out)
                if killers:
                    r["status"] = "killed"
                    break
            else:
                if mid in equivalent:
                    r["status"], r["why_equivalent"] = "equivalent", equivalent[mid]
                else:
                    r["status"] = "survived"
        finally:
            code, out, _ = sh(["patch", "-p1", "-s", "-R", "-i", patch], cwd=src, log=log)
            if code != 0:
                fail("could not revert %s: %s (remove %s and rerun)" % (mid, out.strip(), work))
        r["commit"] = commit
        results.append(r)
        with open(results_path, "a") as f:
            f.write(json.dumps(dict(r, type="mutant")) + "\n")
        print("[%d/%d] %-42s %-14s build %4.0f s, tests %4.0f s  %s" % (
            k + 1, len(chosen), mid, r["status"], r["build_s"], r["test_s"],
            ", ".join(r["killed_by"][:4]) + (" …" if len(r["killed_by"]) > 4 else "")), flush=True)
        if not a.smoke:
            summarise(results_path, rows)

    # The build tree holds the last mutant's programs (its source was reverted, not rebuilt): none
    # may stay where it could be taken for the real tool.
    shutil.rmtree(build, ignore_errors=True)
    counted = [r for r in results if r["status"] in ("killed", "survived")]
    killed = sum(r["status"] == "killed" for r in results)
    score = 100.0 * killed / len(counted) if counted else 0.0
    print("this run's score: %d of %d non-equivalent mutants killed (%.1f %%); %d equivalent, %d do not build" % (
        killed, len(counted), score, sum(r["status"] == "equivalent" for r in results),
        sum(r["status"] == "does-not-build" for r in results)))
    if a.smoke:
        bad = [r["id"] for r in results if r["status"] != "killed"]
        if bad:
            fail("smoke mutants not killed: " + ", ".join(bad))


def stage1_tests(build):
    """Names of the tests that stage 1 builds for: those of its programs, and the tool's scripts."""
    out = subprocess.check_output(["ctest", "--test-dir", build, "--show-only=json-v1"], text=True)
    names = []
    for test in json.loads(out)["tests"]:
        program = os.path.basename((test.get("command") or ["?"])[0])
        if program in STAGE1_TARGETS or (program.startswith("python") and test["name"].startswith(STAGE1_TOOL_TESTS)):
            names.append(test["name"])
    return names


def summarise(results_path, rows):
    """tests/mutation/results/latest.json and .md from WORK/results.jsonl, which every run appends
    to: each mutant's latest record (with the commit it was run at) and the runs those come from."""
    runs, last, earlier = {}, {}, {}
    for line in open(results_path):
        rec = json.loads(line)
        if rec.get("type") == "run":
            runs.setdefault(rec["commit"], []).append(rec)
        else:
            before = last.get(rec["id"])
            if before and before["commit"] != rec["commit"]:
                earlier.setdefault(rec["id"], []).append({"status": before["status"], "commit": before["commit"]})
            last[rec["id"]] = dict(rec, earlier=earlier.get(rec["id"], []))
    ms = [last[r["id"]] for r in rows if r["id"] in last]
    used = {m["commit"] for m in ms} | {e["commit"] for m in ms for e in m["earlier"]}
    used = [c for c in runs if c in used]
    counted = [m for m in ms if m["status"] in ("killed", "survived")]
    summary = {"runs": [run for c in used for run in runs.get(c, [])], "mutants": ms,
               "not_run": [r["id"] for r in rows if r["id"] not in last],
               "score": 100.0 * sum(m["status"] == "killed" for m in ms) / len(counted) if counted else 0.0,
               "written": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")}
    os.makedirs(RESULTS, exist_ok=True)
    with open(os.path.join(RESULTS, "latest.json"), "w") as f:
        json.dump(summary, f, indent=1)
    with open(os.path.join(RESULTS, "latest.md"), "w") as f:
        f.write(markdown(summary))


def markdown(s):
    """The summary that the report includes: score, per-area table, survivors and equivalents."""
    ms = s["mutants"]
    L = ["Per mutant: an incremental -O1 build and the release ctest selection (all but labels `slow` and "
         "`mutation`). Runs recorded here:", ""]
    for run in s["runs"]:
        n = sum(m["commit"] == run["commit"] for m in ms)
        L.append("- commit `%s`%s, started %s: %d of the verdicts below; unmutated, %d tests pass in %d s%s%s." % (
            run["commit"][:12], " (dirty)" if run["dirty"] else "", run["started"], n,
            run["baseline"]["tests"], run["baseline"]["test_s"],
            "; a mutant's ctest stops at its first failing test" if run["stop_on_failure"] else "",
            "; stage 1 (library, tool, core test programs) first, the full build and selection for what "
            "survives it" if run.get("staged") else ""))
    if s["not_run"]:
        L.append("- not run yet: %s" % ", ".join("`%s`" % m for m in s["not_run"]))
    L.append("")
    counted = [m for m in ms if m["status"] in ("killed", "survived")]
    L.append("**Score%s: %d of %d non-equivalent mutants killed (%.1f %%)**; %d argued equivalent, %d do not build." % (
        " so far (%d of %d mutants run; the score of the index needs all)" % (len(ms), len(ms) + len(s["not_run"]))
        if s["not_run"] else "",
        sum(m["status"] == "killed" for m in ms), len(counted), s["score"],
        sum(m["status"] == "equivalent" for m in ms), sum(m["status"] == "does-not-build" for m in ms)))
    L += ["", "| area | mutants | killed | survived | equivalent |", "|---|---|---|---|---|"]
    areas = []
    for m in ms:
        if m["area"] not in areas:
            areas.append(m["area"])
    for area in areas:
        sub = [m for m in ms if m["area"] == area]
        L.append("| %s | %d | %d | %d | %d |" % (area, len(sub), sum(m["status"] == "killed" for m in sub),
                                               sum(m["status"] == "survived" for m in sub),
                                               sum(m["status"] == "equivalent" for m in sub)))
    L += ["", "| mutant | what it breaks | status | killed by | commit | build / tests (s) |", "|---|---|---|---|---|---|"]
    for m in ms:
        killers = m.get("killed_by", [])
        shown = ", ".join("`%s`" % k for k in killers[:3]) + (" and %d more" % (len(killers) - 3) if len(killers) > 3 else "")
        status = m["status"] + "".join(" (before: %s at `%s`)" % (e["status"], e["commit"][:8]) for e in m.get("earlier", []))
        L.append("| `%s` | %s | %s | %s | `%s` | %.0f / %.0f |" % (m["id"], m["breaks"].replace("\\|", "|").replace("|", "\\|"),
                                                                  status, shown or "—",
                                                                  m["commit"][:8], m["build_s"], m["test_s"]))
    eq = [m for m in ms if m["status"] == "equivalent"]
    if eq:
        L += ["", "Equivalent mutants (no input changes any output):", ""]
        L += ["- `%s`: %s" % (m["id"], m["why_equivalent"]) for m in eq]
    sv = [m for m in ms if m["status"] == "survived"]
    if sv:
        L += ["", "Survivors (not yet killed):", ""]
        L += ["- `%s`: %s (%s)" % (m["id"], m["breaks"], m["regime"]) for m in sv]
    return "\n".join(L) + "\n"


if __name__ == "__main__":
    main()
