"""Process helpers shared by the bench drivers (node_bench.py, soak.py)."""
import subprocess


def stop(proc, timeout=10):
    """SIGTERM, then SIGKILL if proc has not exited within timeout seconds."""
    proc.terminate()
    try:
        proc.wait(timeout=timeout)
    except subprocess.TimeoutExpired:
        proc.kill()
