#!/usr/bin/python3
"""bench/update_docs.py on a temporary page with fake tables: the marked blocks are replaced and the rest of
the page kept byte for byte, a second run changes nothing, blocks without a table are kept and named, and a
marker without a table name, a broken block or a table file no marker names fail without touching the page.
Also: docs/benchmarks.md's own markers parse, and every table name the benches write has a marker there.
  test_update_docs.py [--xml FILE]   (JUnit result file for catkin_test_results; exit 1 on a failure)
Standard library only (/usr/bin/python3)."""
import argparse
import glob
import os
import re
import subprocess
import sys
import tempfile
import time
import xml.etree.ElementTree as ET

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
UPDATE = os.path.join(ROOT, "bench", "update_docs.py")
TABLES = os.path.join(ROOT, "bench", "bench_tables.py")

PAGE = """# Page

Intro text, kept.

<!-- bench:alpha -->

| old | alpha |
|---|---|
| 1 | 2 |

<!-- /bench:alpha -->

Between the blocks, kept.

<!-- bench:beta -->
| old beta |
<!-- /bench:beta -->

<!-- bench:gamma -->

| gamma, no fresh table |
|---|

<!-- /bench:gamma -->

The end, kept.
"""


class Failed(Exception):
    pass


def check(cond, what):
    if not cond:
        raise Failed(what)


def run(doc, tables, *extra, env=None):
    e = dict(os.environ)
    e.pop("RISER_SIM_BENCH_TABLES", None)
    e.update(env or {})
    p = subprocess.run(["/usr/bin/python3", UPDATE, "--doc", doc, "--tables", tables] + list(extra),
                       capture_output=True, text=True, env=e, timeout=60)
    return p.returncode, p.stdout, p.stderr


def fixture(tmp, page=PAGE, tables=None):
    doc = os.path.join(tmp, "benchmarks.md")
    with open(doc, "w") as f:
        f.write(page)
    tdir = os.path.join(tmp, "tables")
    os.makedirs(tdir, exist_ok=True)
    for name, text in (tables or {}).items():
        with open(os.path.join(tdir, name + ".md"), "w") as f:
            f.write(text)
    return doc, tdir


def read(path):
    with open(path) as f:
        return f.read()


FRESH = {"alpha": "Made by `x`.\n\n| new | alpha |\n|---|---|\n| 3 | 4 |\n",
         "beta": "| new beta |\n|---|\n| 5 |\n"}


def test_replaces_marked_blocks(tmp):
    doc, tdir = fixture(tmp, tables=FRESH)
    rc, out, err = run(doc, tdir)
    check(rc == 0, "exit %d: %s" % (rc, err))
    new = read(doc)
    expected = PAGE.replace("\n| old | alpha |\n|---|---|\n| 1 | 2 |\n",
                            "\nMade by `x`.\n\n| new | alpha |\n|---|---|\n| 3 | 4 |\n")
    expected = expected.replace("<!-- bench:beta -->\n| old beta |\n",
                                "<!-- bench:beta -->\n\n| new beta |\n|---|\n| 5 |\n\n")
    check(new == expected, "page after the update:\n%s\nexpected:\n%s" % (new, expected))
    check(re.search(r"updated 2: alpha, beta", out), "report of the updated blocks: %s" % out)
    check(re.search(r"kept 1: gamma", out), "report of the kept block: %s" % out)


def test_idempotent(tmp):
    doc, tdir = fixture(tmp, tables=FRESH)
    run(doc, tdir)
    once = read(doc)
    rc, out, err = run(doc, tdir)
    check(rc == 0, "second run exit %d: %s" % (rc, err))
    check(read(doc) == once, "the second run changed the page")
    check(re.search(r"updated 0", out) and re.search(r"same as the fresh table 2: alpha, beta", out),
          "second run's report: %s" % out)
    rc, out, err = run(doc, tdir, "--check")
    check(rc == 0, "--check after the update: exit %d (the page would change)" % rc)


def test_check_mode_changes_nothing(tmp):
    doc, tdir = fixture(tmp, tables=FRESH)
    rc, _, _ = run(doc, tdir, "--check")
    check(rc == 1, "--check with fresh tables: exit %d, expected 1" % rc)
    check(read(doc) == PAGE, "--check wrote the page")


def test_no_tables_keeps_everything(tmp):
    doc, tdir = fixture(tmp)
    rc, out, err = run(doc, os.path.join(tmp, "missing_dir"))
    check(rc == 0, "exit %d: %s" % (rc, err))
    check(read(doc) == PAGE, "the page changed without tables")
    check(re.search(r"kept 3: alpha, beta, gamma", out), "report: %s" % out)


def expect_failure(tmp, page, tables, needle):
    doc, tdir = fixture(tmp, page=page, tables=tables)
    rc, out, err = run(doc, tdir)
    check(rc != 0, "exit 0 where it must fail (%s); stdout: %s" % (needle, out))
    check(needle in err, "error message lacks %r: %s" % (needle, err))
    check(read(doc) == page, "the page was written despite the error")


def test_marker_without_name(tmp):
    for bad in ("<!-- bench: -->", "<!-- bench -->", "<!-- /bench: -->", "<!-- bench:Bad Name -->"):
        page = PAGE.replace("<!-- bench:gamma -->", bad, 1)
        expect_failure(tmp, page, FRESH, "marker without a table name")


def test_orphan_table(tmp):
    tables = dict(FRESH, delta="| delta |\n|---|\n")
    expect_failure(tmp, PAGE, tables, "table file delta.md is referenced by no <!-- bench:delta --> marker")


def test_broken_blocks(tmp):
    expect_failure(tmp, PAGE.replace("<!-- /bench:gamma -->\n", ""), FRESH, "bench:gamma is never closed")
    expect_failure(tmp, PAGE.replace("<!-- /bench:beta -->", "<!-- /bench:alpha -->"), FRESH,
                   "/bench:alpha closes bench:beta")
    expect_failure(tmp, PAGE + "<!-- bench:alpha -->\n<!-- /bench:alpha -->\n", FRESH, "bench:alpha again")
    expect_failure(tmp, PAGE.replace("| old beta |", "<!-- bench:alpha -->"), FRESH, "opens inside bench:beta")
    expect_failure(tmp, PAGE, dict(FRESH, beta="| x |\n<!-- /bench:beta -->\n"), "holds a bench marker")


def test_bench_tables_round_trip(tmp):
    """bench_tables.py write -> update_docs.py: the provenance line and the table land in the block."""
    doc, tdir = fixture(tmp)
    env = dict(os.environ, RISER_SIM_BENCH_TABLES=tdir, RISER_SIM_BENCH_STAMP="a CPU (2 CPUs), 2000-01-01, abc")
    p = subprocess.run(["/usr/bin/python3", TABLES, "write", "gamma", "bench/x.sh --fast"], input="| g |\n|---|\n| 7 |\n",
                       capture_output=True, text=True, env=env, timeout=60)
    check(p.returncode == 0, "bench_tables.py write: %s" % p.stderr)
    p = subprocess.run(["/usr/bin/python3", TABLES, "write", "Bad-Name", "x"], input="| g |\n", capture_output=True,
                       text=True, env=env, timeout=60)
    check(p.returncode != 0, "bench_tables.py accepted the table name Bad-Name")
    p = subprocess.run(["/usr/bin/python3", TABLES, "write", "epsilon", "x"], input="no table here\n",
                       capture_output=True, text=True, env=env, timeout=60)
    check(p.returncode != 0, "bench_tables.py wrote a file without a table row")
    rc, out, err = run(doc, tdir)
    check(rc == 0, "exit %d: %s" % (rc, err))
    check("<!-- bench:gamma -->\n\nMade by `bench/x.sh --fast` on a CPU (2 CPUs), 2000-01-01, abc.\n\n| g |\n|---|\n"
          "| 7 |\n\n<!-- /bench:gamma -->" in read(doc), "gamma block:\n%s" % read(doc))


def test_shipped_page(tmp):
    """docs/benchmarks.md parses, and each table name the benches write (write(...)/MarkdownTable(...)/
    bench_tables.py write in bench/) has its block there."""
    page = os.path.join(ROOT, "docs", "benchmarks.md")
    text = read(page)
    copy, _ = fixture(tmp, page=text)
    rc, out, err = run(copy, os.path.join(tmp, "none"))
    check(rc == 0, "docs/benchmarks.md: %s" % err)
    check(read(copy) == text, "docs/benchmarks.md changed without tables")
    blocks = set(re.findall(r"^<!-- bench:([a-z0-9_]+) -->$", text, re.M))
    written = set()
    for src in glob.glob(os.path.join(ROOT, "bench", "*")):
        if os.path.basename(src) == "bench_tables.py" or not os.path.isfile(src):
            continue
        with open(src, errors="replace") as f:
            s = f.read()
        written |= set(re.findall(r"""(?:bench_tables\.write|MarkdownTable \w+|MarkdownTable)\(\s*["']([a-z0-9_]+)["']""", s))
        written |= set(re.findall(r"bench_tables\.py\"? write ([a-z0-9_]+)", s))
    check(len(written) >= 5, "found only %d table names in bench/: %s" % (len(written), sorted(written)))
    missing = sorted(written - blocks)
    check(not missing, "tables the benches write with no block in docs/benchmarks.md: %s" % missing)


TESTS = [test_replaces_marked_blocks, test_idempotent, test_check_mode_changes_nothing, test_no_tables_keeps_everything,
         test_marker_without_name, test_orphan_table, test_broken_blocks, test_bench_tables_round_trip, test_shipped_page]


def write_junit(results, path):
    suite = ET.Element("testsuite", name="update_docs", tests=str(len(results)),
                       failures=str(sum(1 for _, f, _ in results if f)), errors="0")
    for name, failure, secs in results:
        case = ET.SubElement(suite, "testcase", classname="riser_sim.update_docs", name=name, time="%.2f" % secs)
        if failure:
            ET.SubElement(case, "failure", message=failure.split("\n")[0]).text = failure
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    ET.ElementTree(suite).write(path, encoding="utf-8", xml_declaration=True)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--xml", help="JUnit result file")
    a = ap.parse_args()
    results = []
    for t in TESTS:
        t0 = time.time()
        with tempfile.TemporaryDirectory(prefix="update_docs_") as tmp:
            try:
                t(tmp)
                failure = None
            except Failed as e:
                failure = str(e)
            except Exception as e:  # a defect of the test or the script: reported, not hidden
                failure = "%s: %s" % (type(e).__name__, e)
        results.append((t.__name__, failure, time.time() - t0))
        print("%s %s%s" % ("FAILED" if failure else "ok    ", t.__name__, ": " + failure if failure else ""))
    if a.xml:
        write_junit(results, a.xml)
    bad = sum(1 for _, f, _ in results if f)
    print("%d passed, %d failed" % (len(results) - bad, bad))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
