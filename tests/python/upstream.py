"""Runs MuJoCo's own Python tests (mujoco.bindings_test, mujoco.rollout_test, mujoco.render_test)
from the installed package, leaving out the tests that use the names given after --without
(substrings of their source), and exits non-zero on any failure or error. Prints the totals,
then per module how many ran and were skipped."""

import importlib
import inspect
import os
import sys
import unittest

import mujoco

from absl import flags

flags.FLAGS(sys.argv[:1])  # absltest's flags, parsed with their defaults
modules, without = [], []
args = iter(sys.argv[1:])
for a in args:
    if a == "--without":
        without = list(args)
    else:
        modules.append(a)


def leaves(suite):
    for t in suite:
        if isinstance(t, unittest.TestSuite):
            yield from leaves(t)
        else:
            yield t


kept, left_out, per_module = unittest.TestSuite(), [], {}
for name in modules:
    module = importlib.import_module(name)
    for test in leaves(unittest.defaultTestLoader.loadTestsFromModule(module)):
        method = getattr(test, test._testMethodName)
        source = inspect.getsource(method)
        if any(w in source for w in without):
            left_out.append(test.id())
        else:
            kept.addTest(test)
            per_module.setdefault(name, set()).add(test.id())

gl = getattr(mujoco, "GLContext", None)  # MUJOCO_GL picks it; it sets PYOPENGL_PLATFORM
print(f"GL context: {gl.__module__ + '.' + gl.__name__ if gl else 'none'}, "
      f"PYOPENGL_PLATFORM={os.environ.get('PYOPENGL_PLATFORM')}")
result = unittest.TextTestRunner(stream=sys.stderr, verbosity=2).run(kept)
print(f"ran {result.testsRun}, failures {len(result.failures)}, errors {len(result.errors)}, "
      f"skipped {len(result.skipped)}, left out {len(left_out)}")
skipped = {t.id() for t, _ in result.skipped}
for name in modules:
    ids = per_module.get(name, set())
    print(f"module {name}: ran {len(ids)}, skipped {len(ids & skipped)}")
for t in left_out:
    print(f"left out: {t}")
sys.exit(0 if result.wasSuccessful() else 1)
