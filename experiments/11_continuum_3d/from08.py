"""The axisymmetric references' scripts (../08_continuum_reference/), loaded by file path, so
that this folder shares their CalculiX helpers (the .dat reader, the Swift *PLASTIC table, the
node-set writer) instead of copying them. Python 3 standard library only."""
import importlib.util
import os


def load(name):
    """The module ../08_continuum_reference/<name>.py (its main() does not run)."""
    here = os.path.dirname(os.path.abspath(__file__))
    spec = importlib.util.spec_from_file_location(
        name + "08", os.path.join(here, "..", "08_continuum_reference", name + ".py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module
