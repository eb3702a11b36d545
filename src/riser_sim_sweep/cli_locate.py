"""Where riser_sim_cli is: --cli, then $RISER_SIM_CLI, then beside the program (install space, devel
space), then PATH."""
import os
import shutil
import sys

from .sweep_file import SweepError


def locate_cli(option=None):
    tried = []
    cands = []
    if option:
        cands.append(("--cli", option))
    if os.environ.get("RISER_SIM_CLI"):
        cands.append(("RISER_SIM_CLI", os.environ["RISER_SIM_CLI"]))
    for d in dict.fromkeys([os.path.dirname(os.path.abspath(sys.argv[0])),
                            os.path.dirname(os.path.realpath(sys.argv[0]))]):
        cands.append(("beside the program", os.path.join(d, "riser_sim_cli")))
    on_path = shutil.which("riser_sim_cli")
    if on_path:
        cands.append(("PATH", on_path))
    for where, path in cands:
        if os.path.isfile(path) and os.access(path, os.X_OK):
            return os.path.abspath(path)
        tried.append("%s: %s" % (where, path))
        if where in ("--cli", "RISER_SIM_CLI"):
            raise SweepError("%s: '%s' is not an executable riser_sim_cli" % (where, path))
    raise SweepError("riser_sim_cli not found (tried %s); give --cli PATH or set RISER_SIM_CLI"
                     % ("; ".join(tried) or "PATH"))
