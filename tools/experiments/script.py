# SPDX-License-Identifier: MIT
"""What the measuring scripts (rate_distortion.py, baselines.py) share: messages and exits named by
the script, an argument parser whose errors exit 64, and CSV tables read and written whole."""
import argparse
import csv
import io
import sys

from runner import EXIT_USAGE, atomic_write_text

EXIT_DATA, EXIT_NOINPUT, EXIT_SOFTWARE, EXIT_CANTCREAT = 65, 66, 70, 73


class Script:
    """Messages on stderr prefixed with the script's name."""

    def __init__(self, name):
        self.name = name

    def fail(self, code, message):
        print(f"{self.name}: {message}", file=sys.stderr)
        sys.exit(code)

    def note(self, message):
        print(f"{self.name}: {message}", file=sys.stderr)

    def parser(self, **kwargs):
        """An ArgumentParser that prints the usage and exits EXIT_USAGE on a bad argument."""
        script = self

        class Parser(argparse.ArgumentParser):
            def error(self, message):
                self.print_usage(sys.stderr)
                script.fail(EXIT_USAGE, message)

        return Parser(**kwargs)

    def write_csv(self, path, columns, rows):
        """The rows (dicts) under a header of `columns`, written whole or not at all."""
        buf = io.StringIO()
        w = csv.DictWriter(buf, fieldnames=columns, lineterminator="\n")
        w.writeheader()
        for r in rows:
            w.writerow(r)
        atomic_write_text(path, buf.getvalue())

    def read_csv(self, path, columns):
        """The rows of a table that write_csv wrote, as strings; fails when it cannot be read or
        lacks one of `columns`."""
        try:
            with open(path, newline="") as f:
                rows = list(csv.DictReader(f))
        except OSError as e:
            self.fail(EXIT_NOINPUT, f"{path}: cannot read: {e.strerror}")
        if not rows or set(columns) - set(rows[0]):
            self.fail(EXIT_DATA, f"{path}: expected the columns {', '.join(columns)}")
        return rows
