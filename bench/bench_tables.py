#!/usr/bin/python3
"""The benches' markdown tables: each table is a file <tables>/<name>.md (out/bench/tables, or
RISER_SIM_BENCH_TABLES) that bench/update_docs.py puts into docs/benchmarks.md between
<!-- bench:<name> --> and <!-- /bench:<name> -->. A file is one line naming the command, the machine, the
date and the revision, a blank line, then the table (and any note lines the bench prints with it).

  bench_tables.py write NAME COMMAND < table.md   (the shell benches)
  bench_tables.py stamp                           (the machine/date/revision text)
  bench_tables.py machine COMMAND                 (the page's machine line: <tables>/machine.md)
Standard library only (/usr/bin/python3)."""
import datetime
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
NAME_RE = re.compile(r"^[a-z0-9][a-z0-9_]*$")  # also the marker syntax of update_docs.py


def tables_dir():
    return os.environ.get("RISER_SIM_BENCH_TABLES") or os.path.join(ROOT, "out", "bench", "tables")


def cpu_model():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return "unknown CPU"


def revision():
    try:
        out = subprocess.run(["git", "-C", ROOT, "describe", "--always", "--dirty", "--tags"], capture_output=True,
                             text=True, timeout=10)
        return out.stdout.strip() or "unknown revision"
    except (OSError, subprocess.SubprocessError):
        return "unknown revision"


def stamp():
    """'<CPU model> (<k> CPUs), <date>, <git describe>': RISER_SIM_BENCH_STAMP when set (run_all.sh sets it once
    for every table of a run)."""
    env = os.environ.get("RISER_SIM_BENCH_STAMP")
    if env:
        return env
    return "%s (%d CPUs), %s, %s" % (cpu_model(), os.cpu_count() or 0, datetime.date.today().isoformat(), revision())


def check_name(name):
    if not NAME_RE.match(name):
        raise ValueError("table name '%s': lower-case letters, digits and _ only (the marker syntax)" % name)


def render(command, lines):
    """The file's text: the provenance line, a blank line, the table lines."""
    body = [l.rstrip("\n") for l in lines]
    while body and not body[-1].strip():
        body.pop()
    while body and not body[0].strip():
        body.pop(0)
    if not any(l.lstrip().startswith("|") for l in body):
        raise ValueError("no table row (a line starting with '|') to write")
    for l in body:
        if re.match(r"<!--\s*/?\s*bench\b", l.strip()):
            raise ValueError("a table line holds a bench marker: %r" % l)
    return "Made by `%s` on %s.\n\n%s\n" % (command, stamp(), "\n".join(body))


def write(name, lines, command):
    """Writes <tables>/<name>.md; returns its path."""
    check_name(name)
    text = render(command, lines)
    d = tables_dir()
    os.makedirs(d, exist_ok=True)
    path = os.path.join(d, name + ".md")
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)
    return path


def main(argv):
    if len(argv) >= 2 and argv[1] == "stamp":
        print(stamp())
        return 0
    if len(argv) == 3 and argv[1] == "machine":
        d = tables_dir()
        os.makedirs(d, exist_ok=True)
        with open(os.path.join(d, "machine.md"), "w") as f:
            f.write("Last `%s`: %s.\n" % (argv[2], stamp()))
        return 0
    if len(argv) == 4 and argv[1] == "write":
        try:
            path = write(argv[2], sys.stdin.readlines(), argv[3])
        except ValueError as e:
            print("bench_tables: %s: %s" % (argv[2], e), file=sys.stderr)
            return 1
        print("wrote %s" % path)
        return 0
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv))
