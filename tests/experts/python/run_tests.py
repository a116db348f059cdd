"""Runs the Python expert tests (python3 -m unittest); exits 77 (skipped)
when python3-websockets, which the package needs live, is missing."""

import os
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
PYTHON_DIR = os.environ.get("BEFT_PYTHON_DIR", os.path.join(HERE, "..", "..", "..", "modules", "python"))


def main():
    try:
        import websockets  # noqa: F401
    except ImportError:
        print("skipped: python3-websockets is not installed (apt-get install python3-websockets)")
        return 77
    sys.path[:0] = [PYTHON_DIR, os.path.join(PYTHON_DIR, "examples"), HERE]
    suite = unittest.defaultTestLoader.discover(HERE, pattern="test_*.py", top_level_dir=HERE)
    result = unittest.TextTestRunner(verbosity=2).run(suite)
    return 0 if result.wasSuccessful() else 1


if __name__ == "__main__":
    sys.exit(main())
