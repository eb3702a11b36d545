"""Progress on stderr: cases done (this run + earlier runs), failed, running, elapsed and time left (from
this run's throughput). One rewritten line on a terminal, a line per ~5 % otherwise."""
import sys
import time


def _hms(s):
    s = int(round(s))
    return "%d:%02d:%02d" % (s // 3600, s % 3600 // 60, s % 60)


class Progress:
    def __init__(self, total, earlier, label="cases", stream=None, quiet=False):
        self.total, self.earlier, self.label = total, earlier, label
        self.done = self.failed = 0
        self.t0 = time.monotonic()
        self.stream = stream or sys.stderr
        self.tty = self.stream.isatty()
        self.quiet = quiet
        self.every = max(1, (total - earlier) // 20)

    def update(self, status):
        self.done += 1
        if status not in ("ok", "warning"):
            self.failed += 1
        if self.quiet:
            return
        if self.tty or self.done % self.every == 0 or self.earlier + self.done == self.total:
            self.stream.write(("\r" if self.tty else "") + self.line() + ("" if self.tty else "\n"))
            self.stream.flush()

    def line(self):
        el = time.monotonic() - self.t0
        left = self.total - self.earlier - self.done
        eta = el / self.done * left if self.done else float("nan")
        return "%s %d/%d done (%d earlier), %d failed, elapsed %s, left ~%s" % (
            self.label, self.earlier + self.done, self.total, self.earlier, self.failed, _hms(el),
            _hms(eta) if eta == eta else "?")

    def finish(self):
        if self.tty and not self.quiet:
            self.stream.write("\n")
            self.stream.flush()
