"""The results folder: sweep.json (what the sweep is: its fingerprint), results.csv (one row per finished
case, appended and flushed as each finishes) and cases/<case_id>.json (+ .csv with the kept series, _range.csv with the range graph).

A row is written in one write() after its case file, with SIGINT held off (main.py), so the table is whole
after Ctrl-C; a torn last line (the process killed while writing) is cut on the next open. A folder whose
fingerprint differs is another sweep and is refused."""
import csv
import io
import json
import os

from .sweep_file import SweepError

FIXED_HEAD = ["case", "case_id"]
FIXED_TAIL = ["status", "reason", "warning", "wall_s", "cpu_s", "run_wall_s", "rtf", "exit_code", "worker"]
FINISHED = ("ok", "warning", "diverged", "failed", "refused")


class ResultsFolder:
    """Checked at construction (another sweep's folder is refused), written from create() on."""

    def __init__(self, path, fingerprint, override_cols, value_cols, manifest):
        self.path = path
        self.header = FIXED_HEAD + list(override_cols) + FIXED_TAIL + list(value_cols)
        self.override_cols = list(override_cols)
        self.table = os.path.join(path, "results.csv")
        self.cases_dir = os.path.join(path, "cases")
        man_path = os.path.join(path, "sweep.json")
        manifest = dict(manifest, fingerprint=fingerprint, columns=self.header)
        if os.path.isdir(path) and os.listdir(path):
            if not os.path.isfile(man_path):
                raise SweepError("results folder '%s' is not empty and holds no sweep.json: not a sweep's "
                                 "results; give another --out" % path)
            with open(man_path) as f:
                old = json.load(f)
            if old.get("fingerprint") != fingerprint or old.get("columns") != self.header:
                raise SweepError(
                    "results folder '%s' holds another sweep (fingerprint %s from %s, this one %s: the scene file, "
                    "duration, set, keep or override keys differ); give another --out or delete it"
                    % (path, old.get("fingerprint"), old.get("sweep_file", "?"), fingerprint))
        self.manifest, self.man_path = manifest, man_path
        self.done = self._read_done()

    def create(self):
        """The folder, its sweep.json and the table's header (once the sweep is about to run)."""
        os.makedirs(self.cases_dir, exist_ok=True)
        if not os.path.isfile(self.man_path):
            tmp = self.man_path + ".tmp"
            with open(tmp, "w") as f:
                json.dump(self.manifest, f, indent=1, sort_keys=True, default=str)
            os.replace(tmp, self.man_path)
        if not os.path.isfile(self.table):
            self._append(",".join(self.header) + "\n")

    def _read_done(self):
        """{case_id: status} of the rows already in the table; a torn last line is cut off."""
        if not os.path.isfile(self.table):
            return {}
        with open(self.table, "rb") as f:
            data = f.read()
        if data and not data.endswith(b"\n"):
            data = data[: data.rfind(b"\n") + 1]
            with open(self.table, "r+b") as f:
                f.truncate(len(data))
        rows = list(csv.DictReader(io.StringIO(data.decode())))
        return {r["case_id"]: r["status"] for r in rows if r.get("status") in FINISHED}

    def drop(self, case_ids):
        """Removes the rows of case_ids (their rerun writes new ones): the table is rewritten to a temporary
        file and renamed over the old one."""
        case_ids = set(case_ids)
        if not case_ids:
            return
        with open(self.table, newline="") as f:
            lines = f.read().splitlines(keepends=True)
        head, rows = lines[0], lines[1:]
        keep = [ln for ln, r in zip(rows, csv.DictReader(io.StringIO("".join(lines)))) if r["case_id"] not in case_ids]
        tmp = self.table + ".tmp"
        with open(tmp, "w", newline="") as f:
            f.write(head + "".join(keep))
            f.flush()
            os.fsync(f.fileno())
        os.replace(tmp, self.table)
        for cid in case_ids:
            self.done.pop(cid, None)

    def _append(self, text):
        with open(self.table, "a") as f:
            f.write(text)
            f.flush()
            os.fsync(f.fileno())

    def write(self, case, result):
        """The case file, then its row; a case already in the table is not written twice."""
        if case.case_id in self.done:
            return False
        record = {"case": case.index, "case_id": case.case_id, "overrides": case.overrides}
        record.update({k: v for k, v in result.items() if k not in ("series", "range_graph")})
        tmp = os.path.join(self.cases_dir, case.case_id + ".json.tmp")
        with open(tmp, "w") as f:
            json.dump(record, f, indent=1, sort_keys=True, default=str)
        os.replace(tmp, os.path.join(self.cases_dir, case.case_id + ".json"))
        if result.get("series"):
            with open(os.path.join(self.cases_dir, case.case_id + ".csv"), "w") as f:
                f.write(result["series"])
        if result.get("range_graph"):
            with open(os.path.join(self.cases_dir, case.case_id + "_range.csv"), "w") as f:
                f.write(result["range_graph"])
        row = {"case": case.index, "case_id": case.case_id}
        row.update({k: _cell(case.overrides.get(k)) for k in self.override_cols})
        for k in FIXED_TAIL:
            row[k] = _cell(result.get(k))
        row.update({k: _cell(v) for k, v in result.get("values", {}).items()})
        buf = io.StringIO()
        csv.DictWriter(buf, fieldnames=self.header, extrasaction="ignore", lineterminator="\n").writerow(row)
        self._append(buf.getvalue())
        self.done[case.case_id] = result["status"]
        return True


def _cell(v):
    if v is None:
        return ""
    if isinstance(v, float):
        return "%.9g" % v
    if isinstance(v, (list, dict)):
        return json.dumps(v)
    return str(v).replace("\n", " ")


def read_table(path):
    with open(os.path.join(path, "results.csv"), newline="") as f:
        return list(csv.DictReader(f))
