"""Sea states from a scatter table file: CSV (or whitespace-separated) with a header row, one sea state per
row, e.g. `Hs,Tp,probability`. `columns` maps table columns to scene keys; rows whose `weight_column` is
below `min_weight` (default: 0, i.e. empty bins) are left out."""
import csv

from .sweep_file import SweepError, closest


def read_scatter(spec):
    path = spec["file"]
    try:
        with open(path, newline="") as f:
            text = f.read()
    except OSError as e:
        raise SweepError("scatter.file '%s': %s" % (path, e.strerror))
    lines = [ln for ln in text.splitlines() if ln.strip() and not ln.lstrip().startswith("#")]
    if not lines:
        raise SweepError("scatter.file '%s': no header row" % path)
    delim = "," if "," in lines[0] else None
    rows = list(csv.reader(lines, delimiter=",")) if delim else [ln.split() for ln in lines]
    header = [h.strip() for h in rows[0]]
    for c in list(spec["columns"]) + ([spec["weight_column"]] if spec.get("weight_column") else []):
        if c not in header:
            raise SweepError("scatter: column '%s' is not in %s%s; its header: %s"
                             % (c, path, closest(c, header), ", ".join(header)))
    wcol = spec.get("weight_column")
    min_w = float(spec.get("min_weight", 0.0))
    out = []
    for i, r in enumerate(rows[1:], start=2):
        if len(r) != len(header):
            raise SweepError("scatter.file '%s' row %d: %d fields, the header has %d" % (path, i, len(r), len(header)))
        cell = dict(zip(header, (x.strip() for x in r)))
        try:
            if wcol and float(cell[wcol]) <= min_w:
                continue
            out.append({key: _number(cell[col]) for col, key in spec["columns"].items()})
        except ValueError:
            raise SweepError("scatter.file '%s' row %d: not a number in %s" % (path, i, r))
    if not out:
        raise SweepError("scatter.file '%s': no sea state left (weights <= %g)" % (path, min_w))
    return out


def _number(text):
    v = float(text)
    return int(v) if v.is_integer() and "." not in text and "e" not in text.lower() else v
