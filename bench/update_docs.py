#!/usr/bin/python3
"""Puts the benches' tables into docs/benchmarks.md: every block between <!-- bench:<name> --> and
<!-- /bench:<name> --> is replaced by <tables>/<name>.md (bench/bench_tables.py writes them; default
out/bench/tables, or RISER_SIM_BENCH_TABLES). Reports the blocks it updated, those whose fresh table is
the same, and those with no fresh table (kept as they are). Fails, writing nothing, on a marker without a
table name, an unclosed, unopened, nested or repeated block, or a table file that no marker names.

  bench/update_docs.py [--doc docs/benchmarks.md] [--tables DIR] [--check]
--check: change nothing; exit 1 when the page would change.
Standard library only (/usr/bin/python3)."""
import argparse
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
NAME = r"[a-z0-9][a-z0-9_]*"  # bench/bench_tables.py's NAME_RE
OPEN_RE = re.compile(r"^<!-- bench:(%s) -->$" % NAME)
CLOSE_RE = re.compile(r"^<!-- /bench:(%s) -->$" % NAME)
ANY_MARKER_RE = re.compile(r"^<!--\s*/?\s*bench\b", re.M)  # a line that looks like a marker (not prose quoting one)


class DocError(Exception):
    pass


def parse(lines, doc):
    """[(name, open line index, close line index)] in page order."""
    blocks, open_name, open_at, errors = [], None, None, []
    for i, raw in enumerate(lines):
        line = raw.strip()
        if not ANY_MARKER_RE.match(line):
            continue
        where = "%s:%d" % (doc, i + 1)
        m_open, m_close = OPEN_RE.match(line), CLOSE_RE.match(line)
        if not (m_open or m_close):
            errors.append("%s: marker without a table name (the form is <!-- bench:<name> --> ... "
                          "<!-- /bench:<name> -->, name [a-z0-9_]): %s" % (where, line))
        elif m_open:
            if open_name is not None:
                errors.append("%s: bench:%s opens inside bench:%s (opened at line %d)"
                              % (where, m_open.group(1), open_name, open_at + 1))
            open_name, open_at = m_open.group(1), i
        else:
            name = m_close.group(1)
            if open_name is None:
                errors.append("%s: /bench:%s closes a block that is not open" % (where, name))
            elif name != open_name:
                errors.append("%s: /bench:%s closes bench:%s (opened at line %d)" % (where, name, open_name, open_at + 1))
            else:
                blocks.append((name, open_at, i))
            open_name, open_at = None, None
    if open_name is not None:
        errors.append("%s:%d: bench:%s is never closed" % (doc, open_at + 1, open_name))
    seen = {}
    for name, a, _ in blocks:
        if name in seen:
            errors.append("%s:%d: bench:%s again (first at line %d)" % (doc, a + 1, name, seen[name] + 1))
        seen.setdefault(name, a)
    if errors:
        raise DocError("\n".join(errors))
    return blocks


def tables(directory):
    """{name: text} of <directory>/*.md."""
    found = {}
    if not os.path.isdir(directory):
        return found
    bad = []
    for f in sorted(os.listdir(directory)):
        if not f.endswith(".md"):
            continue
        name = f[:-3]
        if not re.fullmatch(NAME, name):
            bad.append("%s: not a table name ([a-z0-9_])" % os.path.join(directory, f))
            continue
        with open(os.path.join(directory, f)) as fh:
            text = fh.read().strip("\n")
        if not text.strip():
            bad.append("%s: empty" % os.path.join(directory, f))
            continue
        if ANY_MARKER_RE.search("\n".join(l.strip() for l in text.split("\n"))):
            bad.append("%s: holds a bench marker" % os.path.join(directory, f))
            continue
        found[name] = text
    if bad:
        raise DocError("\n".join(bad))
    return found


def update(text, fresh, doc):
    """(new text, updated, same, kept)."""
    lines = text.split("\n")
    blocks = parse(lines, doc)
    names = {b[0] for b in blocks}
    orphans = sorted(set(fresh) - names)
    if orphans:
        raise DocError("\n".join("table file %s.md is referenced by no <!-- bench:%s --> marker in %s"
                                 % (n, n, doc) for n in orphans))
    out, pos, updated, same, kept = [], 0, [], [], []
    for name, a, b in blocks:
        out.extend(lines[pos:a + 1])
        old = lines[a + 1:b]
        if name in fresh:
            new = [""] + fresh[name].split("\n") + [""]
            (same if new == old else updated).append(name)
            out.extend(new)
        else:
            kept.append(name)
            out.extend(old)
        pos = b
    out.extend(lines[pos:])
    return "\n".join(out), updated, same, kept


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--doc", default=os.path.join(ROOT, "docs", "benchmarks.md"))
    ap.add_argument("--tables", default=os.environ.get("RISER_SIM_BENCH_TABLES")
                    or os.path.join(ROOT, "out", "bench", "tables"))
    ap.add_argument("--check", action="store_true", help="change nothing; exit 1 when the page would change")
    a = ap.parse_args()
    doc = os.path.relpath(a.doc) if a.doc.startswith(ROOT) else a.doc
    try:
        with open(a.doc) as f:
            text = f.read()
        new, updated, same, kept = update(text, tables(a.tables), doc)
    except (DocError, OSError) as e:
        print("update_docs: error:\n%s\n%s left as it was" % (e, doc), file=sys.stderr)
        return 1
    print("update_docs: %s: updated %d: %s" % (doc, len(updated), ", ".join(updated) or "-"))
    print("update_docs: same as the fresh table %d: %s" % (len(same), ", ".join(same) or "-"))
    print("update_docs: no fresh table in %s, kept %d: %s" % (a.tables, len(kept), ", ".join(kept) or "-"))
    if a.check:
        return 1 if new != text else 0
    if new != text:
        tmp = a.doc + ".tmp"
        with open(tmp, "w") as f:
            f.write(new)
        os.replace(tmp, a.doc)
    return 0


if __name__ == "__main__":
    sys.exit(main())
