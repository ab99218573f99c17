# SPDX-License-Identifier: BSD-3-Clause
"""What the plugin tests share: their command line, a check that records failures, and the
exit status."""
import argparse
import sys

failures = []


def arguments(*extra):
    """--plugin and --data, plus the named optional arguments."""
    parser = argparse.ArgumentParser()
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--data", required=True)
    for name in extra:
        parser.add_argument(name)
    args, _ = parser.parse_known_args()
    return args


def check(condition, message):
    if not condition:
        failures.append(message)
        print("check failed:", message, file=sys.stderr)


def finish():
    print("%d passed, %d failed" % (1 if not failures else 0, 1 if failures else 0))
    sys.exit(1 if failures else 0)
