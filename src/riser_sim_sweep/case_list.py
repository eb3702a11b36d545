"""The cases of a sweep: the product of the grid axes, the explicit case list and the scatter table's sea
states, each with the base overrides under it. A case's id is a hash of its overrides, so a rerun with more
cases finds the finished ones again."""
import hashlib
import itertools
import json
import re

from .scatter_table import read_scatter


class Case:
    def __init__(self, index, overrides):
        self.index = index
        self.overrides = overrides  # {scene key: value}, in --set order
        blob = json.dumps(sorted(overrides.items()), sort_keys=True, default=str)
        self.case_id = hashlib.sha1(blob.encode()).hexdigest()[:12]

    def set_args(self):
        """CLI --set options; values as JSON, which the CLI's YAML parser reads back exactly."""
        out = []
        for k, v in self.overrides.items():
            out += ["--set", "%s=%s" % (k, format_value(v))]
        return out


PLAIN = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*$")
YAML_WORDS = {"true", "false", "yes", "no", "on", "off", "null", "y", "n", "~"}


def format_value(v):
    """As YAML the CLI reads back exactly: floats by repr, a plain word as itself, the rest as JSON."""
    if isinstance(v, float):
        return repr(v)
    if isinstance(v, str) and PLAIN.match(v) and v.lower() not in YAML_WORDS:
        return v
    return json.dumps(v)


def expand_cases(spec):
    """[Case] in a fixed order (grid axes vary last-fastest, then list, then scatter)."""
    blocks = []
    if spec.grid:
        keys = list(spec.grid)
        blocks.append([dict(zip(keys, combo)) for combo in itertools.product(*(spec.grid[k] for k in keys))])
    if spec.cases:
        blocks.append([dict(c) for c in spec.cases])
    if spec.scatter:
        blocks.append(read_scatter(spec.scatter))
    combos = [{}]
    for block in blocks:
        combos = [dict(a, **b) for a in combos for b in block]
    cases, seen = [], set()
    for c in combos:
        case = Case(len(cases), dict(spec.base, **c))
        if case.case_id not in seen:  # the same overrides twice are one case
            seen.add(case.case_id)
            cases.append(case)
    return cases


def override_keys(cases):
    return list(dict.fromkeys(k for c in cases for k in c.overrides))
