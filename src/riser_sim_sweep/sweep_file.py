"""The sweep file: a base scene, the cases (grid, list, scatter table) and what to keep. Every key is
checked before anything runs; an unknown key is named with the closest known one."""
import difflib
import hashlib
import json
import os

import yaml


class SweepError(ValueError):
    """Bad sweep input; the message names the key or file."""


TOP_KEYS = {
    "scene": "base scene file (relative to the sweep file)",
    "duration": "simulated time of every case [s] (CLI --duration); default: the scene's run.duration",
    "set": "overrides applied to every case: {key: value}",
    "grid": "cartesian product: {key: [values] or {start, stop, step}}",
    "cases": "explicit list of cases: [{key: value, ...}, ...] (product with grid and scatter)",
    "scatter": "sea states from a table file: {file, columns: {column: key}, weight_column, min_weight}",
    "keep": "what each case keeps: {summary, extremes, probes, series, output_dt}",
}
SCATTER_KEYS = {"file", "columns", "weight_column", "min_weight"}
RANGE_KEYS = {"start", "stop", "step"}


def closest(word, choices):
    """' (did you mean X?)' for the nearest of choices, or ''."""
    m = difflib.get_close_matches(str(word), sorted(choices), n=1, cutoff=0.5)
    return " (did you mean '%s'?)" % m[0] if m else ""


def check_keys(where, mapping, allowed):
    if not isinstance(mapping, dict):
        raise SweepError("%s: expected a mapping, got %s" % (where, type(mapping).__name__))
    for k in mapping:
        if k not in allowed:
            raise SweepError("%s: unknown key '%s'%s; known: %s" % (where, k, closest(k, allowed),
                                                                     ", ".join(sorted(allowed))))


def override_key(where, key):
    """A scene key path of --set: dotted words."""
    if not isinstance(key, str) or not key or any(not part for part in key.split(".")) or "=" in key:
        raise SweepError("%s: '%s' is not a scene key path like environment.waves.heading" % (where, key))
    return key


def expand_values(where, spec):
    """A grid axis: a list, or {start, stop, step} with stop included."""
    if isinstance(spec, list):
        if not spec:
            raise SweepError("%s: empty list" % where)
        return spec
    if isinstance(spec, dict):
        check_keys(where, spec, RANGE_KEYS)
        try:
            start, stop, step = (float(spec[k]) for k in ("start", "stop", "step"))
        except KeyError as e:
            raise SweepError("%s: range needs start, stop and step (missing %s)" % (where, e))
        except (TypeError, ValueError):
            raise SweepError("%s: start, stop, step must be numbers" % where)
        if not step > 0 or stop < start:
            raise SweepError("%s: range needs step > 0 and stop >= start" % where)
        count = int((stop - start) / step + 1e-9) + 1
        if count > 100000:
            raise SweepError("%s: %d values, more than 100000" % (where, count))
        as_int = all(float(spec[k]).is_integer() for k in RANGE_KEYS)
        vals = [start + i * step for i in range(count)]
        return [int(round(v)) for v in vals] if as_int else [round(v, 12) for v in vals]
    raise SweepError("%s: expected a list of values or {start, stop, step}" % where)


def file_sha(path):
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


class SweepSpec:
    """A checked sweep: scene path, duration, base overrides, grid axes, explicit cases, scatter, keep."""

    def __init__(self, scene, duration=None, base=None, grid=None, cases=None, scatter=None, keep=None,
                 source="(options)"):
        self.scene = scene
        self.duration = duration
        self.base = base or {}
        self.grid = grid or {}
        self.cases = cases or []
        self.scatter = scatter
        self.keep = keep
        self.source = source

    def fingerprint(self, override_keys):
        """What decides a row's content for given overrides: the scene file's bytes, the duration, the base
        overrides, what is kept and the override columns. Another fingerprint = another sweep."""
        blob = json.dumps({"scene_sha256": file_sha(self.scene), "duration": self.duration, "set": self.base,
                           "keep": self.keep.describe(), "override_keys": sorted(override_keys)},
                          sort_keys=True, default=str)
        return hashlib.sha256(blob.encode()).hexdigest()[:16]


def load_sweep(path):
    """Reads and checks a sweep file (SweepError naming the key)."""
    from .keep import KeepSpec  # noqa: local import keeps the module graph flat

    try:
        with open(path) as f:
            doc = yaml.safe_load(f)
    except OSError as e:
        raise SweepError("sweep file '%s': %s" % (path, e.strerror))
    except yaml.YAMLError as e:
        raise SweepError("sweep file '%s': not YAML: %s" % (path, e))
    if not isinstance(doc, dict):
        raise SweepError("sweep file '%s': expected a mapping of %s" % (path, ", ".join(TOP_KEYS)))
    check_keys("sweep file '%s'" % path, doc, TOP_KEYS)
    base_dir = os.path.dirname(os.path.abspath(path))
    if "scene" not in doc:
        raise SweepError("sweep file '%s': 'scene' (the base scene file) is required" % path)
    scene = os.path.normpath(os.path.join(base_dir, str(doc["scene"])))
    if not os.path.isfile(scene):
        raise SweepError("scene: file '%s' not found" % scene)
    duration = doc.get("duration")
    if duration is not None:
        if isinstance(duration, bool) or not isinstance(duration, (int, float)) or not duration >= 0:
            raise SweepError("duration: expected a number of seconds >= 0, got %r" % (duration,))
        duration = float(duration)
    base = doc.get("set") or {}
    if not isinstance(base, dict):
        raise SweepError("set: expected a mapping {scene key: value}")
    for k in base:
        override_key("set", k)
    grid = {}
    g = doc.get("grid") or {}
    if not isinstance(g, dict):
        raise SweepError("grid: expected a mapping {key: values}")
    for k, v in g.items():
        grid[override_key("grid", k)] = expand_values("grid.%s" % k, v)
    cases = doc.get("cases") or []
    if not isinstance(cases, list):
        raise SweepError("cases: expected a list of {key: value} mappings")
    for i, c in enumerate(cases):
        if not isinstance(c, dict) or not c:
            raise SweepError("cases[%d]: expected a non-empty mapping {key: value}" % i)
        for k in c:
            override_key("cases[%d]" % i, k)
    scatter = doc.get("scatter")
    if scatter is not None:
        check_keys("scatter", scatter, SCATTER_KEYS)
        if "file" not in scatter or "columns" not in scatter:
            raise SweepError("scatter: needs 'file' and 'columns' ({table column: scene key})")
        scatter = dict(scatter)
        scatter["file"] = os.path.normpath(os.path.join(base_dir, str(scatter["file"])))
        if not isinstance(scatter["columns"], dict) or not scatter["columns"]:
            raise SweepError("scatter.columns: expected {table column: scene key}")
        for k in scatter["columns"].values():
            override_key("scatter.columns", k)
    keep = KeepSpec.from_doc(doc.get("keep"))
    return SweepSpec(scene, duration, base, grid, cases, scatter, keep, source=os.path.abspath(path))
