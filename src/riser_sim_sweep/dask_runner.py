"""The Dask side: a LocalCluster of worker processes (one thread each: each task is one CLI process) or an
existing cluster through its scheduler address, and the loop that hands each finished task to a callback.

Dask reschedules the tasks of a worker that dies (up to distributed.scheduler.allowed-failures, 3); a case
that kills its worker every time comes back as KilledWorker and is recorded as failed. SIGINT is held off
while a result is written (InterruptGuard), so an interrupt never tears a row."""
import contextlib
import logging
import os
import signal
import shutil
import tempfile
import uuid
import zipfile

from .sweep_file import SweepError


class InterruptGuard:
    """SIGINT raises KeyboardInterrupt, except inside hold(): then at its end."""

    def __init__(self):
        self.pending = False
        self.holding = False
        self.previous = None

    def __enter__(self):
        self.previous = signal.signal(signal.SIGINT, self._handler)
        return self

    def __exit__(self, *exc):
        signal.signal(signal.SIGINT, self.previous)
        return False

    def _handler(self, signum, frame):
        if self.holding:
            self.pending = True
        else:
            raise KeyboardInterrupt

    @contextlib.contextmanager
    def hold(self):
        self.holding = True
        try:
            yield
        finally:
            self.holding = False
            if self.pending:
                self.pending = False
                raise KeyboardInterrupt


class QuietOnInterrupt:
    """Worker plugin of the local cluster: Ctrl-C in a terminal reaches the worker processes too; they leave
    it to the sweep (which closes the cluster) instead of dying with a traceback each. A Python handler, not
    SIG_IGN: the CLI processes they start get the default action back at exec, so Ctrl-C stops them."""

    def setup(self, worker):
        import threading
        if threading.current_thread() is threading.main_thread():
            signal.signal(signal.SIGINT, lambda signum, frame: None)


def open_client(workers=None, scheduler=None, connect_timeout=10.0):
    """(client, cluster or None). workers: processes of the local cluster (default: every core)."""
    from distributed import Client, LocalCluster

    if scheduler:
        if "://" not in scheduler:
            scheduler = "tcp://" + scheduler
        try:
            client = Client(scheduler, timeout=connect_timeout)
        except (OSError, TimeoutError) as e:
            raise SweepError("--scheduler %s: no Dask scheduler answered within %g s (%s); start one with "
                             "`dask-scheduler` and `dask-worker %s`, or leave --scheduler out for a local cluster"
                             % (scheduler, connect_timeout, e, scheduler))
        # The workers of an existing cluster get this package as a zip (a worker plugin: a worker that joins
        # or restarts later gets it too); they need numpy and riser_sim_cli of their own.
        zip_path = _package_zip()
        try:
            client.upload_file(zip_path)
        finally:
            shutil.rmtree(os.path.dirname(zip_path), ignore_errors=True)
        return client, None
    n = workers or os.cpu_count() or 1
    cluster = LocalCluster(n_workers=n, threads_per_worker=1, processes=True, dashboard_address=None,
                           silence_logs=logging.ERROR)
    client = Client(cluster)
    client.register_worker_plugin(QuietOnInterrupt(), name="riser_sim_sweep-quiet-on-interrupt")
    return client, cluster


def _package_zip():
    pkg = os.path.dirname(os.path.abspath(__file__))
    path = os.path.join(tempfile.mkdtemp(prefix="riser_sim_sweep_zip_"), "riser_sim_sweep_%s.zip" % uuid.uuid4().hex[:8])
    with zipfile.ZipFile(path, "w") as z:
        for name in sorted(os.listdir(pkg)):
            if name.endswith(".py"):
                z.write(os.path.join(pkg, name), "riser_sim_sweep/" + name)
    return path


def close_client(client, cluster):
    with contextlib.suppress(Exception):
        client.close(timeout=5)
    if cluster is not None:
        with contextlib.suppress(Exception):
            cluster.close(timeout=5)


def run_tasks(client, fn, items, on_result, guard, label):
    """items: [(tag, task)]; on_result(tag, result dict) for each as it finishes (inside guard.hold()).
    A task that raised (KilledWorker: its workers died) gives {"status": "failed", "reason": ...}."""
    from distributed import as_completed

    token = uuid.uuid4().hex[:8]
    futures = {}
    for tag, task in items:
        f = client.submit(fn, task, key="%s-%s-%s" % (label, token, task["case_id"]), pure=False)
        futures[f] = tag
    try:
        for fut in as_completed(list(futures)):
            tag = futures[fut]
            if fut.status == "finished":
                result = fut.result()
            else:
                exc = fut.exception()
                name = type(exc).__name__
                why = ("its worker died every time it ran (distributed.scheduler.allowed-failures)"
                       if name == "KilledWorker" else str(exc))
                result = {"case_id": tag.case_id, "status": "failed", "reason": "%s: %s" % (name, why),
                          "values": {}}
            with guard.hold():
                on_result(tag, result)
            fut.release()
    finally:
        pending = [f for f in futures if not f.done()]
        if pending:
            with contextlib.suppress(Exception):
                client.cancel(pending)
