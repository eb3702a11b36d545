"""What a case keeps from its run: final summary values, extremes over time of time-series columns, probes
(rfe K's columns), time series stored per case, the range graph (envelopes along the arc length). Each kind
says which CLI options it needs and which table columns it fills; a new kind is one more entry in KINDS."""
import io

import numpy as np

from .sweep_file import SweepError, check_keys, closest

KINDS = {
    "summary": "summary JSON keys: the value at the end of the run (table column: the key)",
    "extremes": "time-series columns: min and max over the run (columns min_<col>, max_<col>)",
    "probes": "rfe indices K: min and max of tension_rfeK, x/y/z_rfeK (CLI --probe-rfe K)",
    "series": "time-series columns stored per case in cases/<case_id>.csv (t first)",
    "output_dt": "time-series row interval [s]; default: every step (extremes see every step)",
    "range_graph": "true: the CLI's --range-graph per case in cases/<case_id>_range.csv (min/max per station "
                   "over every step) and its extremes over the line (columns range_*)",
}
# Table columns of keep.range_graph: (column, range-graph CSV columns, the pick over the stations). The planar
# bending moment is signed (3D: its size): its largest size is over both envelopes.
RANGE_COLUMNS = (("range_tension_min", ("tension_min",), "min"), ("range_tension_max", ("tension_max",), "max"),
                 ("range_moment_abs_max", ("moment_min", "moment_max"), "absmax"),
                 ("range_curvature_max", ("curvature_max",), "max"),
                 ("range_clearance_min", ("clearance_min",), "min"))
PROBE_COLUMNS = ("tension_rfe%d", "x_rfe%d", "y_rfe%d", "z_rfe%d")
DEFAULT_EXTREMES = ["tension_top", "tension_max", "x_end", "y_end", "z_end"]


def _names(where, v):
    if v is None:
        return []
    if not isinstance(v, list) or not all(isinstance(x, str) and x for x in v):
        raise SweepError("%s: expected a list of names" % where)
    return list(dict.fromkeys(v))


class KeepSpec:
    def __init__(self, summary=None, extremes=None, probes=None, series=None, output_dt=None, range_graph=False):
        self.summary = summary or []
        self.range_graph = bool(range_graph)
        self.extremes = DEFAULT_EXTREMES[:] if extremes is None else extremes
        self.probes = probes or []
        self.series = series or []
        self.output_dt = output_dt

    @staticmethod
    def from_doc(doc):
        if doc is None:
            return KeepSpec()
        check_keys("keep", doc, KINDS)
        probes = doc.get("probes") or []
        if not isinstance(probes, list) or not all(isinstance(k, int) and not isinstance(k, bool) and k >= 0
                                                   for k in probes):
            raise SweepError("keep.probes: expected a list of rfe indices >= 0")
        out_dt = doc.get("output_dt")
        if out_dt is not None and (isinstance(out_dt, bool) or not isinstance(out_dt, (int, float)) or not out_dt > 0):
            raise SweepError("keep.output_dt: expected a number of seconds > 0")
        rg = doc.get("range_graph", False)
        if not isinstance(rg, bool):
            raise SweepError("keep.range_graph: expected true or false")
        ex = doc.get("extremes")
        return KeepSpec(_names("keep.summary", doc.get("summary")),
                        None if ex is None else _names("keep.extremes", ex), sorted(set(probes)),
                        _names("keep.series", doc.get("series")), None if out_dt is None else float(out_dt), rg)

    def describe(self):
        d = {"summary": self.summary, "extremes": self.extremes, "probes": self.probes, "series": self.series,
             "output_dt": self.output_dt}
        if self.range_graph:  # only when asked: a sweep.json written before this kind keeps its fingerprint
            d["range_graph"] = True
        return d

    def series_columns(self):
        """Time-series columns read from the CLI's CSV."""
        cols = list(self.extremes)
        for k in self.probes:
            cols += [c % k for c in PROBE_COLUMNS]
        return list(dict.fromkeys(cols + self.series))

    def needs_csv(self):
        return bool(self.series_columns())

    def cli_args(self, csv_path, range_path=None):
        args = ["--summary", "--quiet"]
        if self.range_graph and range_path:
            args += ["--range-graph", range_path]
        if self.needs_csv():
            # Every step unless asked: the CLI's stride is round(output_dt / dt), at least 1.
            args += ["--csv", csv_path, "--output-dt", repr(self.output_dt or 1e-9)]
            for k in self.probes:
                args += ["--probe-rfe", str(k)]
        return args

    def columns(self):
        """Table columns filled by extract(), in order."""
        cols = list(self.summary)
        ex = list(self.extremes) + [c % k for k in self.probes for c in PROBE_COLUMNS]
        for c in dict.fromkeys(ex):
            cols += ["min_" + c, "max_" + c]
        if self.range_graph:
            cols += [c for c, _, _ in RANGE_COLUMNS]
        return cols

    def validate(self, summary_keys, csv_header):
        """Every kept name exists in what the CLI writes for this scene (SweepError with the closest name)."""
        for k in self.summary:
            if k not in summary_keys:
                raise SweepError("keep.summary: '%s' is not a summary key of this scene%s; known: %s"
                                 % (k, closest(k, summary_keys), ", ".join(sorted(summary_keys))))
        for where, names in (("keep.extremes", self.extremes), ("keep.series", self.series)):
            for c in names:
                if c not in csv_header:
                    raise SweepError("%s: '%s' is not a time-series column of this scene%s; known: %s"
                                     % (where, c, closest(c, csv_header), ", ".join(csv_header)))

    def extract(self, summary, csv_text):
        """Table values and the kept series (text) from a finished run's summary and CSV."""
        values = {k: summary.get(k) for k in self.summary}
        series_text = None
        if self.needs_csv() and csv_text:
            header = csv_text.split("\n", 1)[0].strip().split(",")
            data = np.loadtxt(io.StringIO(csv_text), delimiter=",", skiprows=1, ndmin=2)
            col = {c: i for i, c in enumerate(header)}
            ex = list(self.extremes) + [c % k for k in self.probes for c in PROBE_COLUMNS]
            for c in dict.fromkeys(ex):
                if c in col and data.shape[0] > 0:
                    v = data[:, col[c]]
                    values["min_" + c], values["max_" + c] = float(np.min(v)), float(np.max(v))
            if self.series and data.shape[0] > 0:
                idx = [col["t"]] + [col[c] for c in self.series if c in col]
                buf = io.StringIO()
                np.savetxt(buf, data[:, idx], delimiter=",", fmt="%.9g",
                           header=",".join(["t"] + [c for c in self.series if c in col]), comments="")
                series_text = buf.getvalue()
        return values, series_text

    def extract_range(self, range_text):
        """The range_* table values from the CLI's range-graph CSV: the least or largest over the stations
        (a column the scene has not, e.g. the clearance without a seabed, stays empty)."""
        if not self.range_graph or not range_text:
            return {}
        header = range_text.split("\n", 1)[0].strip().split(",")
        data = np.genfromtxt(io.StringIO(range_text), delimiter=",", skip_header=1, ndmin=2)
        values = {}
        for name, cols, pick in RANGE_COLUMNS:
            if all(c in header for c in cols) and data.shape[0] > 0:
                v = np.concatenate([data[:, header.index(c)] for c in cols])
                v = v[np.isfinite(v)]  # the last station has no joint: its moment and curvature are empty
                if v.size:
                    values[name] = float(np.min(v) if pick == "min" else np.max(np.abs(v) if pick == "absmax" else v))
        return values
